#include "viewer/solution_vtp.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "radiosity/core/errors.h"
#include "viewer/solution_polydata.h"
#include "viewer/solution_vtp_layout.h"

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
  // zlib's fastest level: Sponza's solution (82k elements) in 0.20 s and 7.0 MB, against VTK's
  // default (5) 0.35 s and 6.9 MB.
  writer->SetCompressionLevel(1);
  writer->WriteToOutputStringOn();
  if (!writer->Write()) throw RuntimeFailure("VTK could not write the solution PolyData");
  const std::string& bytes = writer->GetOutputString();
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

namespace {

// VTK's reader checks the XML, not what the numbers mean: a hostile file could name points that
// do not exist (the viewer would index past its arrays), or hold NaN, negative areas or ids that
// are not ints. What the viewer relies on is checked here.
void checkSolutionValues(const std::string& path, vtkPolyData* data) {
  const vtkIdType points = data->GetNumberOfPoints(), cells = data->GetNumberOfCells();
  for (vtkIdType p = 0; p < points; ++p) {
    double x[3];
    data->GetPoint(p, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      throw InputError(path, 0, "point " + std::to_string(p) + " is not finite");
  }
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = data->GetPolys();
  polys->InitTraversal();
  for (vtkIdType cell = 0; polys->GetNextCell(n, ids); ++cell)
    for (vtkIdType k = 0; k < n; ++k)
      if (ids[k] < 0 || ids[k] >= points)
        throw InputError(path, 0,
                         "triangle " + std::to_string(cell) + " names point " +
                             std::to_string(ids[k]) + " of " + std::to_string(points));
  for (const char* name : {solution_array::radiosity, solution_array::radiance,
                           solution_array::unshot, solution_array::area}) {
    const bool isArea = std::string(name) == solution_array::area;
    vtkDataArray* a = data->GetCellData()->GetArray(name);
    for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
      for (int c = 0; c < a->GetNumberOfComponents(); ++c) {
        const double v = a->GetComponent(t, c);
        if (!std::isfinite(v) || (isArea && v < 0))
          throw InputError(path, 0,
                           std::string("cell array '") + name + "' holds " + std::to_string(v) +
                               " at cell " + std::to_string(t));
      }
  }
  vtkDataArray* pointRadiance = data->GetPointData()->GetArray(solution_array::radiance);
  for (vtkIdType t = 0; t < points; ++t)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(pointRadiance->GetComponent(t, c)))
        throw InputError(path, 0,
                         "point array 'radiance' is not finite at point " + std::to_string(t));
  // Ids and levels are ints in the solver; any array type may hold them in a file.
  for (const char* name :
       {solution_array::patch, solution_array::material, solution_array::level}) {
    vtkDataArray* a = data->GetCellData()->GetArray(name);
    for (vtkIdType t = 0; t < cells; ++t) {
      const double v = a->GetComponent(t, 0);
      if (!(v >= 0 && v <= std::numeric_limits<int>::max()) || v != std::floor(v))
        throw InputError(path, 0,
                         std::string("cell array '") + name + "' holds " + std::to_string(v) +
                             " at cell " + std::to_string(t) + ": expected a whole number >= 0");
    }
  }
}

}  // namespace

vtkSmartPointer<vtkPolyData> readSolutionVtp(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, 0, "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) throw InputError(path, 0, "cannot open the file");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path, 0, "cannot read the file");
  // VTK's reader trusts the counts in the file; it only sees bytes whose layout is ours, and
  // the very bytes that were checked (read from memory, not the file again).
  checkSolutionVtpLayout(path, bytes);
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->ReadFromInputStringOn();
  reader->SetInputString(bytes);
  std::string().swap(bytes);  // the reader keeps its own copy
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
  checkSolutionValues(path, data);
  return data;
}

std::string solutionSceneFile(vtkPolyData* solution) {
  auto* scene = vtkStringArray::SafeDownCast(solution->GetFieldData()->GetAbstractArray("scene"));
  return scene && scene->GetNumberOfValues() > 0 ? scene->GetValue(0) : std::string();
}

}  // namespace rad
