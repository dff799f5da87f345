// The light probes' spheres (viewer/probe_polydata.h), no window needed: spheres closed, outward
// and centred at the probes, every vertex coloured with the tone-mapped probeIrradiance(n)/π of
// its normal, probes inside geometry left out, and the radius from the grid's spacing.
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <set>

#include "radiosity/core/check.h"
#include "viewer/probe_polydata.h"

namespace rad {
namespace {

// A probe lit from above: a uniform term plus a gradient towards +y (Y1,-1 ∝ y).
ProbeSh litFromAbove(const Eigen::Vector3d& position, double level) {
  ProbeSh p;
  p.position = position;
  p.coefficients[0] = Rgb::all(level);
  p.coefficients[1] = Rgb(0.5, 0.4, 0.3) * level;
  p.coefficients[6] = Rgb(0.05, -0.02, 0.0) * level;  // some order-2 shape too
  return p;
}

Eigen::Vector3d pointOf(vtkPolyData* data, vtkIdType i) {
  double x[3];
  data->GetPoint(i, x);
  return {x[0], x[1], x[2]};
}

TEST(ProbePolyData, VertexColoursAreTheToneMappedIrradianceOfTheirNormals) {
  std::vector<ProbeSh> probes = {litFromAbove({0, 0, 0}, 1.0), litFromAbove({1, 0, 0}, 2.0),
                                 litFromAbove({0, 1, 0}, 3.0), litFromAbove({1, 1, 0}, 0.5)};
  probes[2].inside = true;
  const ToneMap toneMap{0.7};
  const double radius = 0.1;
  for (const int segments : {4, 8, 16}) {
    const auto data = makeProbePolyData(probes, radius, toneMap, segments);
    const int bands = segments / 2;
    const vtkIdType perSphere = 2 + segments * (bands - 1);
    ASSERT_EQ(data->GetNumberOfPoints(), 3 * perSphere) << segments;  // the inside one left out
    ASSERT_EQ(data->GetNumberOfCells(), 3 * 2 * segments * (bands - 1)) << segments;
    auto* colours =
        vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetArray(probe_array::srgb));
    auto* index = data->GetPointData()->GetArray(probe_array::probe);
    ASSERT_TRUE(colours && index);
    EXPECT_EQ(data->GetPointData()->GetScalars(), colours);
    std::set<int> seen;
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
      const int p = static_cast<int>(index->GetComponent(i, 0));
      seen.insert(p);
      const Eigen::Vector3d offset = pointOf(data, i) - probes[p].position;
      EXPECT_NEAR(offset.norm(), radius, 1e-6) << i;
      const Eigen::Vector3d n = offset.normalized();
      const auto expected = toneMap.toSrgb8(probeIrradiance(probes[p], n) / M_PI);
      for (int c = 0; c < 3; ++c)  // points are f32: the normal read back is off by ~1e-7
        EXPECT_NEAR(colours->GetValue(3 * i + c), expected[c], 1) << i << " channel " << c;
    }
    EXPECT_EQ(seen, (std::set<int>{0, 1, 3})) << "the inside probe is hidden";

    // Each sphere is closed (every edge in two triangles, once each way) and faces out: its
    // signed volume is positive and near 4/3 π r³ (within the faceting's loss).
    std::map<std::pair<vtkIdType, vtkIdType>, int> edges;
    std::map<int, double> volume;
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    auto* polys = data->GetPolys();
    polys->InitTraversal();
    while (polys->GetNextCell(n, ids)) {
      ASSERT_EQ(n, 3);
      const int p = static_cast<int>(index->GetComponent(ids[0], 0));
      const Eigen::Vector3d a = pointOf(data, ids[0]) - probes[p].position,
                            b = pointOf(data, ids[1]) - probes[p].position,
                            c = pointOf(data, ids[2]) - probes[p].position;
      volume[p] += a.dot(b.cross(c)) / 6;
      for (int k = 0; k < 3; ++k) ++edges[{ids[k], ids[(k + 1) % 3]}];
    }
    for (const auto& [edge, count] : edges) {
      EXPECT_EQ(count, 1) << segments;
      EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << segments << ": an open edge";
    }
    const double ball = 4.0 / 3 * M_PI * radius * radius * radius;
    for (const auto& [p, v] : volume) {
      EXPECT_GT(v, (segments == 4 ? 0.3 : 0.6) * ball) << segments;
      EXPECT_LT(v, ball) << segments;
    }
  }
}

// The test that fails if the colours were upside down or unlit: a probe lit from above shows a
// bright top and a dark bottom, and a brighter probe is brighter everywhere.
TEST(ProbePolyData, ProbeLitFromAboveIsBrighterOnTop) {
  const std::vector<ProbeSh> probes = {litFromAbove({0, 0, 0}, 0.6), litFromAbove({3, 0, 0}, 1.2)};
  const auto data = makeProbePolyData(probes, 0.5, ToneMap{1.0}, 16);
  auto* colours = data->GetPointData()->GetArray(probe_array::srgb);
  auto* index = data->GetPointData()->GetArray(probe_array::probe);
  std::map<int, double> top, bottom;
  std::map<int, double> sum;
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    const int p = static_cast<int>(index->GetComponent(i, 0));
    const double y = pointOf(data, i).y() - probes[p].position.y();
    const double grey = colours->GetComponent(i, 0) + colours->GetComponent(i, 1);
    if (y > 0.49) top[p] = grey;
    if (y < -0.49) bottom[p] = grey;
    sum[p] += grey;
  }
  ASSERT_EQ(top.size(), 2u);
  ASSERT_EQ(bottom.size(), 2u);
  for (int p = 0; p < 2; ++p) EXPECT_GT(top[p], bottom[p] + 50) << p;
  EXPECT_GT(sum[1], sum[0]);
}

TEST(ProbePolyData, RadiusIsFromTheGridSpacingAndResolutionFromTheCount) {
  std::vector<ProbeSh> grid;
  for (const Eigen::Vector3d& x : probeGrid({0, 0, 0}, {0.556, 0.549, 0.56}, 0.2)) {
    ProbeSh p;
    p.position = x.cast<float>().cast<double>();  // as probes.bin stores them
    grid.push_back(p);
  }
  ASSERT_EQ(grid.size(), 27u);
  EXPECT_NEAR(probeSphereRadius(grid, 1.0), 0.15 * 0.2, 1e-6);
  // A flat grid (one z), and a lone probe or none: the fallback.
  std::vector<ProbeSh> flat(2);
  flat[1].position = {0.5, 0, 0};
  EXPECT_NEAR(probeSphereRadius(flat, 1.0), 0.075, 1e-12);
  EXPECT_EQ(probeSphereRadius({ProbeSh{}}, 0.25), 0.25);
  EXPECT_EQ(probeSphereRadius({}, 0.25), 0.25);
  EXPECT_EQ(probeSphereRadius(std::vector<ProbeSh>(3), 0.25), 0.25);  // all at one point
  // Irregular probes: never larger than 0.15 × the nearest pair's distance.
  std::vector<ProbeSh> loose(3);
  loose[1].position = {1, 0.3, 0};
  loose[2].position = {5, 5, 5};
  EXPECT_LE(probeSphereRadius(loose, 1.0), 0.15 * loose[1].position.norm());

  EXPECT_EQ(probeSphereSegments(27), 16);
  EXPECT_EQ(probeSphereSegments(10000), 16);
  EXPECT_EQ(probeSphereSegments(10001), 8);
  EXPECT_EQ(probeSphereSegments(1000000), 4);
  EXPECT_EQ(makeProbePolyData({}, 0.1, ToneMap{}, 16)->GetNumberOfPoints(), 0);
  EXPECT_THROW(makeProbePolyData(grid, 0.1, ToneMap{}, 5), CheckFailure);
}

}  // namespace
}  // namespace rad
