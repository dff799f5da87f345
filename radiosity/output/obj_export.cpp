#include "radiosity/output/obj_export.h"

#include <charconv>
#include <string>

#include "radiosity/core/check.h"

namespace rad {
namespace {

// The shortest text that reads back as the same float: enough for positions and UVs.
// (std::to_chars: a third of the time snprintf's "%.9g" took on Sponza's 280k numbers.)
void appendNumber(std::string& text, double x) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, static_cast<float>(x)).ptr;
  text.append(buf, end);
}

void appendVector(std::string& text, const char* prefix, std::initializer_list<double> xs) {
  text += prefix;
  for (double x : xs) {
    text += ' ';
    appendNumber(text, x);
  }
  text += '\n';
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
  std::string text;  // the whole file, written at once
  for (const auto& p : mesh.positions) appendVector(text, "v", {p.x(), p.y(), p.z()});
  for (const auto& t : mesh.uvs) appendVector(text, "vt", {t.x(), 1.0 - t.y()});
  for (const auto& n : mesh.normals) {
    const Eigen::Vector3d u = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : n;
    appendVector(text, "vn", {u.x(), u.y(), u.z()});
  }
  for (int page = 0; page < pages; ++page)
    for (size_t m = 0; m < mesh.materialNames.size(); ++m) {
      bool any = false;
      for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (mesh.materials[t] != static_cast<int>(m) || mesh.pages[t] != page) continue;
        if (!any) text += "usemtl " + materialName(m, page) + '\n', any = true;
        text += 'f';
        for (int k = 0; k < 3; ++k) {
          char index[16];
          const auto end = std::to_chars(index, index + sizeof index, mesh.triangles[t][k] + 1).ptr;
          for (int repeat = 0; repeat < 3; ++repeat) {  // v/vt/vn share the index
            text += repeat == 0 ? ' ' : '/';
            text.append(index, end);
          }
        }
        text += '\n';
      }
    }
  obj << text;
}

}  // namespace rad
