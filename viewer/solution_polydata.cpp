#include "viewer/solution_polydata.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <string>

#include "meshing/vertex_interpolation.h"
#include "radiosity/core/check.h"

namespace rad {
namespace {

template <typename Array>
vtkSmartPointer<Array> namedArray(const char* name, int components, vtkIdType tuples) {
  auto a = vtkSmartPointer<Array>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

// Area-weighted means at the points of per-cell RGB values.
std::vector<Rgb> pointMeans(vtkPolyData* data, const std::vector<Rgb>& perCell) {
  auto* area = vtkDoubleArray::SafeDownCast(data->GetCellData()->GetArray(solution_array::area));
  std::vector<Rgb> sum(data->GetNumberOfPoints());
  std::vector<double> weight(data->GetNumberOfPoints(), 0.0);
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  auto* polys = data->GetPolys();
  polys->InitTraversal();
  for (vtkIdType cell = 0; polys->GetNextCell(n, ids); ++cell) {
    const double w = area ? area->GetValue(cell) : 1.0;
    for (vtkIdType k = 0; k < n; ++k) {
      sum[ids[k]] += w * perCell[cell];
      weight[ids[k]] += w;
    }
  }
  for (size_t p = 0; p < sum.size(); ++p)
    if (weight[p] > 0) sum[p] = sum[p] / weight[p];
  return sum;
}

}  // namespace

vtkSmartPointer<vtkPolyData> makeSolutionPolyData(const PatchMesh& mesh,
                                                  const std::vector<Rgb>& radiosity,
                                                  const std::vector<Rgb>& unshot,
                                                  const ToneMap& toneMap) {
  const int count = mesh.elementCount();
  RAD_CHECK_EQ(radiosity.size(), count);
  const VertexInterpolation vertices(mesh);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vertices.vertexCount());
  for (int v = 0; v < vertices.vertexCount(); ++v) {
    const Eigen::Vector3d& p = vertices.position(v);
    points->SetPoint(v, p.x(), p.y(), p.z());
  }
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->AllocateExact(count, 3 * count);
  auto area = namedArray<vtkDoubleArray>(solution_array::area, 1, count);
  auto patch = namedArray<vtkIntArray>(solution_array::patch, 1, count);
  auto material = namedArray<vtkIntArray>(solution_array::material, 1, count);
  auto level = namedArray<vtkIntArray>(solution_array::level, 1, count);
  for (int e = 0; e < count; ++e) {
    const auto& t = vertices.triangle(e);
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    triangles->InsertNextCell(3, ids);
    area->SetValue(e, mesh.area(e));
    patch->SetValue(e, mesh.patch(e));
    material->SetValue(e, mesh.material(e));
    level->SetValue(e, mesh.level(e));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(triangles);
  for (vtkDataArray* a : {static_cast<vtkDataArray*>(area), static_cast<vtkDataArray*>(patch),
                          static_cast<vtkDataArray*>(material), static_cast<vtkDataArray*>(level)})
    data->GetCellData()->AddArray(a);
  setSolutionArrays(data, radiosity, unshot, toneMap);
  return data;
}

void setSolutionArrays(vtkPolyData* data, const std::vector<Rgb>& radiosity,
                       const std::vector<Rgb>& unshot, const ToneMap& toneMap) {
  const vtkIdType cells = data->GetNumberOfCells();
  RAD_CHECK_EQ(radiosity.size(), cells);
  if (!unshot.empty()) RAD_CHECK_EQ(unshot.size(), cells);
  auto b = namedArray<vtkDoubleArray>(solution_array::radiosity, 3, cells);
  auto radiance = namedArray<vtkDoubleArray>(solution_array::radiance, 3, cells);
  auto remaining = namedArray<vtkDoubleArray>(solution_array::unshot, 3, cells);
  auto colour = namedArray<vtkUnsignedCharArray>(solution_array::srgb, 3, cells);
  std::vector<Rgb> cellRadiance(cells);
  for (vtkIdType e = 0; e < cells; ++e) {
    const Rgb& v = radiosity[e];
    cellRadiance[e] = v / M_PI;
    const Rgb u = unshot.empty() ? Rgb{} : unshot[e];
    const auto c = toneMap.toSrgb8(cellRadiance[e]);
    for (int k = 0; k < 3; ++k) {
      b->SetComponent(e, k, v[k]);
      radiance->SetComponent(e, k, cellRadiance[e][k]);
      remaining->SetComponent(e, k, u[k]);
      colour->SetComponent(e, k, c[k]);
    }
  }
  for (vtkDataArray* a :
       {static_cast<vtkDataArray*>(b), static_cast<vtkDataArray*>(radiance),
        static_cast<vtkDataArray*>(remaining), static_cast<vtkDataArray*>(colour)})
    data->GetCellData()->AddArray(a);  // replaces the array of the same name

  const std::vector<Rgb> vertexRadiance = pointMeans(data, cellRadiance);
  const vtkIdType points = data->GetNumberOfPoints();
  auto pointRadiance = namedArray<vtkDoubleArray>(solution_array::radiance, 3, points);
  auto pointColour = namedArray<vtkUnsignedCharArray>(solution_array::srgb, 3, points);
  for (vtkIdType p = 0; p < points; ++p) {
    const auto c = toneMap.toSrgb8(vertexRadiance[p]);
    for (int k = 0; k < 3; ++k) {
      pointRadiance->SetComponent(p, k, vertexRadiance[p][k]);
      pointColour->SetComponent(p, k, c[k]);
    }
  }
  data->GetPointData()->AddArray(pointRadiance);
  data->GetPointData()->AddArray(pointColour);

  auto exposure = namedArray<vtkDoubleArray>(solution_array::exposure, 1, 1);
  exposure->SetValue(0, toneMap.exposure);
  data->GetFieldData()->AddArray(exposure);
  data->Modified();
}

std::vector<double> pointAverages(vtkPolyData* data, const std::vector<double>& cellValues) {
  std::vector<Rgb> asRgb(cellValues.size());
  for (size_t i = 0; i < cellValues.size(); ++i) asRgb[i] = Rgb::all(cellValues[i]);
  const std::vector<Rgb> means = pointMeans(data, asRgb);
  std::vector<double> out(means.size());
  for (size_t p = 0; p < means.size(); ++p) out[p] = means[p].r;
  return out;
}

ToneMap solutionToneMap(vtkPolyData* data) {
  if (auto* e =
          vtkDoubleArray::SafeDownCast(data->GetFieldData()->GetArray(solution_array::exposure)))
    if (e->GetNumberOfTuples() == 1 && e->GetValue(0) > 0 && std::isfinite(e->GetValue(0)))
      return ToneMap{e->GetValue(0)};
  auto* radiance = data->GetCellData()->GetArray(solution_array::radiance);
  auto* area = data->GetCellData()->GetArray(solution_array::area);
  std::vector<Rgb> values;
  std::vector<double> weights;
  for (vtkIdType c = 0; radiance && area && c < radiance->GetNumberOfTuples(); ++c) {
    values.push_back(
        {radiance->GetComponent(c, 0), radiance->GetComponent(c, 1), radiance->GetComponent(c, 2)});
    weights.push_back(std::max(0.0, area->GetComponent(c, 0)));
  }
  return ToneMap::autoExposure(values, weights);
}

}  // namespace rad
