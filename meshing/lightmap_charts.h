#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "meshing/patch_mesh.h"

namespace rad {

// Lightmap charts: groups of adjacent patches (input polygons) with similar normals, each
// flattened by a planar projection into its own 2D frame without folds or overlaps. The layout
// of the charts in an atlas is lightmap_packing.h's job.
struct LightmapChartOptions {
  // A patch joins a chart when its normal is within this angle of the chart's first patch.
  double maxAngleDegrees = 30.0;
};

struct LightmapChart {
  std::vector<int> elements;
  std::vector<int> patches;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // the projection direction (unit)
  Eigen::Vector2d size = Eigen::Vector2d::Zero();    // extent of the flattened chart, scene units
};

struct LightmapCharts {
  std::vector<LightmapChart> charts;
  std::vector<int> chartOfElement;
  // Each element corner in its chart's frame (scene units; the chart's bounding box starts at
  // the origin and is the smallest over the convex hull's edge directions).
  std::vector<std::array<Eigen::Vector2d, 3>> corners;
};

LightmapCharts buildLightmapCharts(const PatchMesh& mesh, const LightmapChartOptions& options = {});

// True when the interiors of two 2D triangles overlap by more than `eps` (touching edges and
// shared vertices do not count). Used to keep charts free of folds and overlaps.
bool trianglesOverlap2d(const std::array<Eigen::Vector2d, 3>& a,
                        const std::array<Eigen::Vector2d, 3>& b, double eps);

}  // namespace rad
