#include "radiosity/output/obj_export.h"

#include <cstdio>

#include "radiosity/core/check.h"

namespace rad {
namespace {

// Shortest text that reads back as the same float: enough for positions and UVs.
std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

}  // namespace

void writeBakedObj(std::ostream& obj, std::ostream& mtl, const BakedMesh& mesh,
                   const std::string& mtlName, const std::vector<std::string>& pageTextures) {
  RAD_CHECK_EQ(mesh.uvs.size(), mesh.positions.size());  // lightmap UVs, one per vertex
  RAD_CHECK_GE(pageTextures.size(), 1u);
  const int pages = static_cast<int>(pageTextures.size());
  auto materialName = [&](size_t m, int page) {
    return mesh.materialNames[m] + (pages > 1 ? "_page" + std::to_string(page) : "");
  };
  mtl << "# radiosity bake: the lightmap holds outgoing radiance, tone-mapped; shown unlit (illum "
         "0)\n";
  for (int page = 0; page < pages; ++page)
    for (size_t m = 0; m < mesh.materialNames.size(); ++m)
      mtl << "newmtl " << materialName(m, page)
          << "\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nillum 0\nmap_Kd " << pageTextures[page] << "\n\n";

  obj << "# radiosity bake: positions, normals and lightmap UVs (vt, v up)\n";
  obj << "mtllib " << mtlName << "\n";
  for (const auto& p : mesh.positions)
    obj << "v " << num(p.x()) << ' ' << num(p.y()) << ' ' << num(p.z()) << '\n';
  for (const auto& t : mesh.uvs) obj << "vt " << num(t.x()) << ' ' << num(1.0 - t.y()) << '\n';
  for (const auto& n : mesh.normals) {
    const Eigen::Vector3d u = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : n;
    obj << "vn " << num(u.x()) << ' ' << num(u.y()) << ' ' << num(u.z()) << '\n';
  }
  for (int page = 0; page < pages; ++page)
    for (size_t m = 0; m < mesh.materialNames.size(); ++m) {
      bool any = false;
      for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (mesh.materials[t] != static_cast<int>(m) || mesh.pages[t] != page) continue;
        if (!any) obj << "usemtl " << materialName(m, page) << '\n', any = true;
        obj << 'f';
        for (int k = 0; k < 3; ++k) {
          const int i = mesh.triangles[t][k] + 1;
          obj << ' ' << i << '/' << i << '/' << i;
        }
        obj << '\n';
      }
    }
}

}  // namespace rad
