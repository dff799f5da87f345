#pragma once

#include <Eigen/Core>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <array>
#include <utility>
#include <vector>

namespace rad {

// Double precision everywhere in the mesh (DESIGN: float only at the Embree and VTK boundaries).
struct PatchMeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<PatchMeshTraits>;

// One input polygon: the unit of material and of the scene's description.
struct PatchPolygon {
  PatchPolygon() = default;
  PatchPolygon(std::vector<int> vertices, int material, std::vector<Eigen::Vector2d> uvs = {},
               std::vector<Eigen::Vector2d> lightmapUvs = {})
      : vertices(std::move(vertices)),
        material(material),
        uvs(std::move(uvs)),
        lightmapUvs(std::move(lightmapUvs)) {}

  std::vector<int> vertices;  // indices into the positions array, counter-clockwise from the front
  int material = 0;
  // Texture coordinates per corner (the scene's own UVs), or empty: polygons with and without
  // them may be mixed.
  std::vector<Eigen::Vector2d> uvs;
  // A second set for lightmaps (glTF's TEXCOORD_1), or empty: then `uvs` serve as that set too.
  std::vector<Eigen::Vector2d> lightmapUvs;
};

// The meshed scene: patches (input polygons) split into triangular elements, kept conforming
// (no T-vertices) so values interpolate across shared edges without cracks. Elements are the
// mesh's faces, numbered 0..elementCount()-1; that index is used by every later stage.
class PatchMesh {
 public:
  PatchMesh(const std::vector<Eigen::Vector3d>& positions,
            const std::vector<PatchPolygon>& polygons);

  int elementCount() const { return static_cast<int>(mesh_.n_faces()); }
  int patchCount() const { return patchCount_; }
  // Triangles the input polygons were split into, before any subdivision.
  int inputTriangleCount() const { return inputTriangles_; }
  int vertexCount() const { return static_cast<int>(mesh_.n_vertices()); }

  int patch(int element) const { return mesh_.property(patchId_, face(element)); }
  int material(int element) const { return mesh_.property(materialId_, face(element)); }
  double area(int element) const { return mesh_.property(area_, face(element)); }
  // Unit geometric normal of the element's front side (right-hand rule on its corners).
  Eigen::Vector3d normal(int element) const;
  Eigen::Vector3d centroid(int element) const;
  std::array<int, 3> cornerVertices(int element) const;
  std::array<Eigen::Vector3d, 3> corners(int element) const;
  Eigen::Vector3d position(int vertex) const;
  // Whether every element carries its input polygon's texture coordinates.
  bool hasUvs() const { return allUvs_; }
  // Whether this element does (its polygon had them).
  bool hasUvs(int element) const { return anyUvs_ && mesh_.property(uvs_, face(element)).valid; }
  // The texture coordinates at the element's corners (cornerVertices order), linear over its
  // polygon's triangles: a vertex made by bisection takes the mean of its edge's two ends.
  // Requires hasUvs(element).
  std::array<Eigen::Vector2d, 3> cornerUvs(int element) const;
  // The same for the lightmap set (a polygon's lightmapUvs, else its uvs): whether every element
  // has it (bake --use-scene-uvs needs that), and its corners. Requires hasLightmapUvs().
  bool hasLightmapUvs() const { return allLightmapUvs_; }
  std::array<Eigen::Vector2d, 3> cornerLightmapUvs(int element) const;
  // How many times the element's ancestry was bisected (0 for the patch's own triangles).
  int level(int element) const { return mesh_.property(level_, face(element)); }

  double totalArea() const;
  double patchArea(int patch) const;
  Eigen::Vector3d boundsMin() const { return boundsMin_; }
  Eigen::Vector3d boundsMax() const { return boundsMax_; }
  double boundsDiagonal() const { return (boundsMax_ - boundsMin_).norm(); }

  // Shooting patches (substructuring): markShooters() makes every current element a shooter;
  // elements split afterwards stay in their parent's shooter, so shooters tile the surface with
  // triangles coarser than the elements. Before markShooters(), each element is its own shooter.
  void markShooters();
  int shooterCount() const {
    return shootersMarked_ ? static_cast<int>(shooterCorners_.size()) : elementCount();
  }
  int shooter(int element) const {
    return shootersMarked_ ? mesh_.property(shooterId_, face(element)) : element;
  }
  std::array<Eigen::Vector3d, 3> shooterCorners(int shooter) const {
    return shootersMarked_ ? shooterCorners_[shooter] : corners(shooter);
  }
  double shooterArea(int shooter) const;

  // Splits elements by longest-edge bisection until none is larger than maxArea. Conforming:
  // a split edge splits both faces beside it (Rivara's LEPP keeps the triangles well shaped).
  void subdivideUniform(double maxArea);
  // Splits the largest element (by bisection, as above) until there are at least `count`
  // elements: the requested count is met (one split adds one to three elements) and the sizes
  // stay within about a factor 2 of each other wherever the input allows.
  void subdivideToCount(int count);
  // Bisects one element (and neighbours as needed to stay conforming). Returns the number of
  // elements added.
  int bisect(int element);

  // Shape of an element: its longest edge over the altitude onto that edge (2/√3 ≈ 1.15 for an
  // equilateral triangle, 2 for the halves of a square; a sliver's is large).
  double aspectRatio(int element) const;
  // Splits slivers into well-shaped elements (sliver_splitting.cpp): elements whose aspectRatio
  // exceeds maxAspect and whose longest edge is above minEdge have their longest edge on the
  // patch's outline split at its midpoint, then edges inside a patch are flipped to the
  // Delaunay triangulation, in rounds until none is left. Conforming throughout. Longest-edge
  // bisection alone keeps a sliver's shape at every level; the flips are what turn a long strip
  // into short, well-shaped pieces. A corner of an input polygon sharper than the bound, a strip
  // narrower than minEdge, and a sliver with no outline edge about as long as its longest edge
  // are left so.
  void splitSlivers(double maxAspect, double minEdge);

  const TriMesh& mesh() const { return mesh_; }
  static TriMesh::FaceHandle face(int element) { return TriMesh::FaceHandle(element); }

 private:
  // Per-face texture coordinates, keyed by vertex: the corners of a face are found by walking
  // its half-edges, whose starting corner an edge split may change.
  // Both sets share the corner keys; the lightmap set follows the texture set through splits.
  struct FaceUvs {
    std::array<int, 3> vertex{};
    std::array<double, 6> uv{};          // (u, v) per entry of `vertex`: texture set
    std::array<double, 6> lightmapUv{};  // the same for the lightmap set
    bool valid = false;                  // false: the face's polygon had no texture coordinates
    bool lightmapValid = false;          // false: it had no lightmap coordinates either
  };
  std::array<Eigen::Vector2d, 3> cornerSet(int element, bool lightmap) const;
  void addTriangle(TriMesh::VertexHandle a, TriMesh::VertexHandle b, TriMesh::VertexHandle c,
                   int patch, int material, const Eigen::Vector2d* uvs,
                   const Eigen::Vector2d* lightmapUvs);
  TriMesh::EdgeHandle longestEdge(TriMesh::FaceHandle f) const;
  void refineAcross(TriMesh::FaceHandle f, int depth);
  void splitEdge(TriMesh::EdgeHandle e);
  void splitUvs(TriMesh::FaceHandle f, int from, int to, int mid);
  void updateArea(TriMesh::FaceHandle f);
  // Lawson flips inside each planar patch until every such edge is locally Delaunay.
  int flipToDelaunay();
  bool shouldFlip(TriMesh::EdgeHandle e) const;
  void flipEdge(TriMesh::EdgeHandle e);
  double longestEdgeLength(int element) const;
  // An edge on the patch's outline: a mesh boundary, a border between patches or a crease.
  bool isPatchBorder(TriMesh::EdgeHandle e) const;
  bool splitSliver(int element);  // false when it has no outline edge long enough to split

  TriMesh mesh_;
  OpenMesh::FPropHandleT<int> patchId_, materialId_, level_, shooterId_;
  std::vector<std::array<Eigen::Vector3d, 3>> shooterCorners_;
  bool shootersMarked_ = false;
  OpenMesh::FPropHandleT<double> area_;
  OpenMesh::FPropHandleT<FaceUvs> uvs_;  // only when anyUvs_
  bool anyUvs_ = false, allUvs_ = false, allLightmapUvs_ = false;
  int patchCount_ = 0;
  int inputTriangles_ = 0;
  // Faces whose shape changed in the last splitEdge/flipEdge calls (cleared by their callers).
  std::vector<int> touched_;
  Eigen::Vector3d boundsMin_, boundsMax_;
};

}  // namespace rad
