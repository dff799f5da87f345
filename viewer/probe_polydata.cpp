#include "viewer/probe_polydata.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

#include "radiosity/core/check.h"

namespace rad {
namespace {

// The unit sphere's points, poles first and last, and its triangles (counter-clockwise seen from
// outside).
struct UnitSphere {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
};

UnitSphere unitSphere(int segments) {
  const int bands = segments / 2;
  UnitSphere s;
  s.points.emplace_back(0, 1, 0);
  for (int i = 1; i < bands; ++i) {
    const double theta = M_PI * i / bands;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * M_PI * j / segments;
      s.points.emplace_back(std::sin(theta) * std::cos(phi), std::cos(theta),
                            std::sin(theta) * std::sin(phi));
    }
  }
  s.points.emplace_back(0, -1, 0);
  const int south = static_cast<int>(s.points.size()) - 1;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) {
    s.triangles.push_back({0, ring(1, j + 1), ring(1, j)});
    for (int i = 1; i + 1 < bands; ++i) {
      s.triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
      s.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
    }
    s.triangles.push_back({south, ring(bands - 1, j), ring(bands - 1, j + 1)});
  }
  return s;
}

}  // namespace

int probeSphereSegments(std::size_t probes) {
  if (probes <= 10000) return 16;
  if (probes <= 100000) return 8;
  return 4;
}

double probeSphereRadius(const std::vector<ProbeSh>& probes, double fallback) {
  double gap = INFINITY;
  for (int a = 0; a < 3; ++a) {
    std::vector<double> c;
    c.reserve(probes.size());
    for (const ProbeSh& p : probes) c.push_back(p.position[a]);
    std::sort(c.begin(), c.end());
    if (c.size() < 2) break;
    const double tiny = 1e-6 * (c.back() - c.front());
    for (size_t i = 1; i < c.size(); ++i)
      if (c[i] - c[i - 1] > tiny) gap = std::min(gap, c[i] - c[i - 1]);
  }
  return std::isfinite(gap) && gap > 0 ? 0.15 * gap : fallback;
}

vtkSmartPointer<vtkPolyData> makeProbePolyData(const std::vector<ProbeSh>& probes, double radius,
                                               const ToneMap& toneMap, int segments) {
  RAD_CHECK_MSG(segments >= 4 && segments % 2 == 0, "sphere segments must be even and >= 4");
  const UnitSphere sphere = unitSphere(segments);
  const vtkIdType perSphere = static_cast<vtkIdType>(sphere.points.size());
  vtkIdType shown = 0;
  for (const ProbeSh& p : probes) shown += !p.inside;

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(shown * perSphere);
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetName(probe_array::srgb);
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(shown * perSphere);
  auto index = vtkSmartPointer<vtkIntArray>::New();
  index->SetName(probe_array::probe);
  index->SetNumberOfTuples(shown * perSphere);
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->AllocateExact(shown * static_cast<vtkIdType>(sphere.triangles.size()),
                           shown * 3 * static_cast<vtkIdType>(sphere.triangles.size()));

  vtkIdType base = 0;
  for (size_t i = 0; i < probes.size(); ++i) {
    const ProbeSh& probe = probes[i];
    if (probe.inside) continue;
    for (vtkIdType v = 0; v < perSphere; ++v) {
      const Eigen::Vector3d& n = sphere.points[v];
      const Eigen::Vector3d x = probe.position + radius * n;
      points->SetPoint(base + v, x.x(), x.y(), x.z());
      const auto srgb = toneMap.toSrgb8(probeIrradiance(probe, n) / M_PI);
      colours->SetTypedTuple(base + v, srgb.data());
      index->SetValue(base + v, static_cast<int>(i));
    }
    for (const auto& t : sphere.triangles) {
      const vtkIdType ids[3] = {base + t[0], base + t[1], base + t[2]};
      triangles->InsertNextCell(3, ids);
    }
    base += perSphere;
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(triangles);
  data->GetPointData()->SetScalars(colours);
  data->GetPointData()->AddArray(index);
  return data;
}

}  // namespace rad
