// Clustering keeps the link count about linear in the input patches: a generated room of N boxes
// (like the benchmark's scene_generator.py), solved and refined with --link-epsilon 0.05 and
// 16 rays per receiver (so sources below 1/16 of a receiver's hemisphere are not
// split: LinkOracle's resolution cap) at 10³ … 10⁵ patches (measured: 338,728, 2,075,161 and
// 22,688,609 links at 1,021, 10,093 and 99,853 patches, exponent 0.92; 41 s and 0.8 GB in all); the
// fitted exponent of links against patches must stay at or below 1.2 (issue 16). Counts, not times:
// timings are in bench/.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "radiosity/hierarchical/hierarchical_radiosity.h"

namespace rad {
namespace {

struct Room {
  std::vector<Eigen::Vector3d> positions;
  std::vector<PatchPolygon> polygons;  // material 0 wall, 1 box, 2 light
};

void addBox(Room& room, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, bool inward) {
  const int base = static_cast<int>(room.positions.size());
  for (int i = 0; i < 8; ++i)
    room.positions.emplace_back((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(),
                                (i & 4) ? hi.z() : lo.z());
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};  // outward, CCW
  for (const auto& f : faces) {
    std::vector<int> v = {base + f[0], base + f[1], base + f[2], base + f[3]};
    if (inward) std::reverse(v.begin(), v.end());
    room.polygons.emplace_back(v, inward ? 0 : 1);
  }
}

Room room(int boxes) {
  Room r;
  const double size = 10, height = 3;
  addBox(r, {0, 0, 0}, {size, height, size}, true);
  const int base = static_cast<int>(r.positions.size());
  const double a = 0.4 * size, b = 0.6 * size, y = height - 1e-3;
  r.positions.insert(r.positions.end(), {{a, y, a}, {b, y, a}, {b, y, b}, {a, y, b}});
  r.polygons.emplace_back(std::vector<int>{base, base + 1, base + 2, base + 3}, 2);
  const int k = std::max(1, static_cast<int>(std::round(std::sqrt(boxes))));
  const double cell = size / (k + 1);
  std::mt19937 rng(1);
  // Boxes keep their shape as they get more and smaller (heights scale with the cell, unlike
  // bench/scene_generator.py's fixed 0.3–1.5), so the room is the same scene at every N.
  std::uniform_real_distribution<double> width(0.2, 0.4), tall(0.5, 2.0);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const double cx = (i + 1) * cell, cz = (j + 1) * cell, w = cell * width(rng);
      addBox(r, {cx - w, 0, cz - w}, {cx + w, cell * tall(rng), cz + w}, false);
    }
  return r;
}

// The room is meshed as `solve` meshes it, into elements of bounded size (the walls into many,
// a small box's faces into one or two each): the per-link bound is relative to the emitted power
// per element, which assumes elements of comparable size.
constexpr double kMaxArea = 0.05;

TEST(HierarchicalLinkGrowth, LinksGrowAboutLinearlyWithPatches) {
  std::vector<double> logPatches, logLinks;
  for (int boxes : {166, 1666, 16666}) {
    const Room r = room(boxes);
    PatchMesh mesh(r.positions, r.polygons);
    mesh.subdivideUniform(kMaxArea);
    const RayCaster rays(mesh);
    RadiosityProblem problem;
    const Rgb reflectance[3] = {Rgb::all(0.7), Rgb(0.8, 0.6, 0.5), Rgb::all(0.5)};
    for (int e = 0; e < mesh.elementCount(); ++e) {
      const int m = r.polygons[mesh.patch(e)].material;
      problem.emission.push_back(m == 2 ? Rgb::all(10 * M_PI) : Rgb());
      problem.reflectance.push_back(reflectance[m]);
      problem.area.push_back(mesh.area(e));
    }
    HierarchicalOptions options;
    options.raysPerReceiver = 16;  // counts of links, not their accuracy
    options.linkEpsilon = 0.05;
    HierarchicalRadiosity hr(mesh, rays, problem, options);
    for (int pass = 0; pass < 6; ++pass) {
      while (hr.solver().progress() > 1e-4 && hr.solver().iterations() < 1000) hr.solver().step();
      if (hr.refineLinks() == 0) break;
    }
    logPatches.push_back(std::log(static_cast<double>(mesh.patchCount())));
    logLinks.push_back(std::log(static_cast<double>(hr.links().size())));
    std::printf("%d patches, %d elements: %lld links\n", mesh.patchCount(), mesh.elementCount(),
                static_cast<long long>(hr.links().size()));
    RecordProperty("links_" + std::to_string(mesh.patchCount()), std::to_string(hr.links().size()));
  }
  // Least-squares slope of log links against log patches.
  const int n = static_cast<int>(logPatches.size());
  double mx = 0, my = 0;
  for (int k = 0; k < n; ++k) {
    mx += logPatches[k] / n;
    my += logLinks[k] / n;
  }
  double sxy = 0, sxx = 0;
  for (int k = 0; k < n; ++k) {
    sxy += (logPatches[k] - mx) * (logLinks[k] - my);
    sxx += (logPatches[k] - mx) * (logPatches[k] - mx);
  }
  const double exponent = sxy / sxx;
  std::printf("link count exponent %.3f\n", exponent);
  EXPECT_LE(exponent, 1.2);
}

}  // namespace
}  // namespace rad
