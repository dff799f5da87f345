#include "viewer/solution_vtp.h"

#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <filesystem>

#include "radiosity/core/errors.h"
#include "viewer/solution_polydata.h"

namespace rad {

void writeSolutionVtp(std::ostream& out, const PatchMesh& mesh, const std::vector<Rgb>& radiosity,
                      const std::vector<Rgb>& unshot, const ToneMap& toneMap,
                      const std::string& sceneFile) {
  vtkSmartPointer<vtkPolyData> data = makeSolutionPolyData(mesh, radiosity, unshot, toneMap);
  auto scene = vtkSmartPointer<vtkStringArray>::New();
  scene->SetName("scene");
  scene->InsertNextValue(sceneFile);
  data->GetFieldData()->AddArray(scene);
  writeSolutionVtp(out, data);
}

void writeSolutionVtp(std::ostream& out, vtkPolyData* solution) {
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetInputData(solution);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw bytes: smaller and faster than base64
  writer->SetCompressorTypeToZLib();
  writer->WriteToOutputStringOn();
  if (!writer->Write()) throw RuntimeFailure("VTK could not write the solution PolyData");
  const std::string& bytes = writer->GetOutputString();
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

vtkSmartPointer<vtkPolyData> readSolutionVtp(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, 0, "no such file");
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  if (!reader->CanReadFile(path.c_str()))
    throw InputError(path, 0, "not a VTK XML PolyData (.vtp) file");
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> data = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || !data || data->GetNumberOfCells() == 0)
    throw InputError(path, 0, "unreadable or empty PolyData");
  const vtkIdType cells = data->GetNumberOfCells();
  if (data->GetNumberOfPolys() != cells) throw InputError(path, 0, "expected triangles only");

  struct Expected {
    const char* name;
    int components;
    bool cell;
  };
  const Expected expected[] = {
      {solution_array::radiosity, 3, true}, {solution_array::radiance, 3, true},
      {solution_array::unshot, 3, true},    {solution_array::area, 1, true},
      {solution_array::patch, 1, true},     {solution_array::material, 1, true},
      {solution_array::level, 1, true},     {solution_array::radiance, 3, false},
  };
  for (const Expected& e : expected) {
    vtkDataArray* a =
        e.cell ? data->GetCellData()->GetArray(e.name) : data->GetPointData()->GetArray(e.name);
    const std::string what = std::string(e.cell ? "cell" : "point") + " array '" + e.name + "'";
    if (!a) throw InputError(path, 0, "missing " + what + ": not a radiosity solution");
    if (a->GetNumberOfComponents() != e.components ||
        a->GetNumberOfTuples() != (e.cell ? cells : data->GetNumberOfPoints()))
      throw InputError(path, 0, what + " has the wrong size");
  }
  if (data->GetPolys()->IsHomogeneous() != 3) throw InputError(path, 0, "expected triangles only");
  return data;
}

std::string solutionSceneFile(vtkPolyData* solution) {
  auto* scene = vtkStringArray::SafeDownCast(solution->GetFieldData()->GetAbstractArray("scene"));
  return scene && scene->GetNumberOfValues() > 0 ? scene->GetValue(0) : std::string();
}

}  // namespace rad
