#include "radiosity/scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/scene/obj_line_check.h"
#include "radiosity/scene/obj_textures.h"

namespace rad {
namespace {

// A face whose area is below this fraction of the squared bounding-box diagonal is degenerate:
// relative, so that the test means the same in millimetres and in kilometres.
constexpr double kDegenerateAreaFraction = 1e-12;
constexpr int kMaxListedLines = 5;

Rgb toRgb(const tinyobj::real_t* c) { return {c[0], c[1], c[2]}; }

SurfaceKind surfaceKind(int illum) {
  if (illum == 3 || illum == 5) return SurfaceKind::Mirror;
  if (illum == 7) return SurfaceKind::Dielectric;
  return SurfaceKind::Diffuse;
}

std::string lineList(const std::vector<int>& lines) {
  std::string text;
  for (std::size_t i = 0; i < lines.size() && i < kMaxListedLines; ++i) {
    text += (i ? ", " : "") + std::to_string(lines[i]);
  }
  if (lines.size() > kMaxListedLines) text += ", ...";
  return text;
}

// The material's images: map_Kd multiplies Kd, map_Ke multiplies Ke, map_d (or the alpha of
// map_Kd, when it has transparent texels) cuts the surface out.
void attachTextures(Material& material, const MaterialSource& source, ObjTextureLoader& loader,
                    const std::vector<Texture>& textures) {
  if (source.diffuseMap.present() &&
      (material.diffuseTexture = loader.colour(source.diffuseMap)) >= 0) {
    material.alphaFromDiffuse = hasTransparentTexel(textures[material.diffuseTexture]);
    // Maya and 3ds Max write Kd 0 0 0 with a map_Kd to mean "the texture alone": read literally
    // it would make the surface black, which no one who attached a texture means.
    if (material.diffuse.maxComponent() == 0) {
      material.diffuse = Rgb::all(1);
      logInfo(source.file + ":" + std::to_string(source.line) + ": material '" + source.name +
              "' has Kd 0 0 0 and a map_Kd: using the texture alone (Kd 1 1 1), as the "
              "exporters that write this mean");
    }
  }
  if (source.emissionMap.present() &&
      (material.emissionTexture = loader.colour(source.emissionMap)) >= 0) {
    if (material.emission.maxComponent() == 0)
      logWarning(source.emissionMap.file + ":" + std::to_string(source.emissionMap.line) +
                 ": material '" + source.name +
                 "' has a map_Ke but Ke 0 0 0: the map multiplies Ke, so the surface emits "
                 "nothing");
  }
  if (source.coverageMap.present()) material.alphaTexture = loader.coverage(source.coverageMap);
}

Material convertMaterial(const tinyobj::material_t& m, const MaterialSource& source) {
  if (m.name != source.name) {
    throw RuntimeFailure(source.file + ":" + std::to_string(source.line) +
                         ": tinyobjloader read material '" + source.name + "' as '" + m.name + "'");
  }
  Material material;
  material.name = m.name;
  material.diffuse = toRgb(m.diffuse);
  material.emission = toRgb(m.emission);
  material.specular = toRgb(m.specular);
  material.transmittance = toRgb(m.transmittance);
  material.ior = m.ior;
  material.shininess = m.shininess;
  material.illum = m.illum;
  material.kind = surfaceKind(m.illum);
  material.sourceFile = source.file;
  material.sourceLine = source.line;

  // The line check validated the text with strtod; tinyobjloader parses numbers its own way, so
  // the Scene's invariants are checked once more on the values it actually produced.
  const bool finite = material.diffuse.isFinite() && material.emission.isFinite() &&
                      material.specular.isFinite() && material.transmittance.isFinite() &&
                      std::isfinite(material.ior) && std::isfinite(material.shininess);
  if (!finite || material.diffuse.minComponent() < 0 || material.diffuse.maxComponent() > 1 ||
      material.emission.minComponent() < 0) {
    throw InputError(source.file, source.line,
                     "material '" + source.name +
                         "': values out of range after parsing (reflectance must be in [0, 1], "
                         "emission non-negative)");
  }
  return material;
}

Material defaultMaterial(const std::string& objPath) {
  Material material;
  material.name = "default";
  material.diffuse = Rgb::all(0.5);
  material.sourceFile = objPath;
  return material;
}

std::vector<Eigen::Vector3d> readPositions(const tinyobj::attrib_t& attrib,
                                           const ObjLineCheck& check, const std::string& objPath) {
  const std::size_t count = attrib.vertices.size() / 3;
  if (static_cast<long>(count) != check.vertexCount) {
    throw RuntimeFailure("tinyobjloader read " + std::to_string(count) + " vertices, expected " +
                         std::to_string(check.vertexCount));
  }
  std::vector<Eigen::Vector3d> positions(count);
  for (std::size_t i = 0; i < count; ++i) {
    positions[i] = {attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]};
    // The line check accepted only finite numbers, but tinyobjloader parses them again its own
    // way: a number it reads as NaN or infinity must not reach the mesh (it would turn every
    // triangle touching the vertex into NaN area).
    if (!positions[i].allFinite()) {
      throw InputError(objPath, check.vertexLines[i],
                       "tinyobjloader reads this vertex as a non-finite position: write its "
                       "numbers in plain decimal notation");
    }
  }
  return positions;
}

double squaredDiagonal(const std::vector<Eigen::Vector3d>& positions) {
  if (positions.empty()) return 0;
  Eigen::Vector3d lo = positions.front(), hi = positions.front();
  for (const Eigen::Vector3d& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).squaredNorm();
}

// Repeated vertices (by index or by position) or an area that is zero at the scene's scale.
bool isDegenerate(const std::vector<int>& vertices, const std::vector<Eigen::Vector3d>& positions,
                  double diagonal2) {
  const std::size_t n = vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (vertices[i] == vertices[j] || positions[vertices[i]] == positions[vertices[j]]) {
        return true;
      }
    }
  }
  // Newell's formula: twice the vector area of a (possibly non-planar) polygon.
  Eigen::Vector3d twiceArea = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    twiceArea += positions[vertices[i]].cross(positions[vertices[(i + 1) % n]]);
  }
  return 0.5 * twiceArea.norm() <= kDegenerateAreaFraction * diagonal2;
}

// Polygons in file order, each mapped back to its `f` line. With triangulate = false
// tinyobjloader keeps one face per `f`, and its shapes hold them in file order.
std::vector<ScenePolygon> readPolygons(const std::vector<tinyobj::shape_t>& shapes,
                                       const std::vector<tinyobj::real_t>& texcoords,
                                       const ObjLineCheck& check, int materialCount) {
  std::vector<ScenePolygon> polygons;
  polygons.reserve(check.faceLines.size());
  for (const tinyobj::shape_t& shape : shapes) {
    std::size_t offset = 0;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const std::size_t k = polygons.size();
      const int size = shape.mesh.num_face_vertices[f];
      if (k >= check.faceLines.size() || size != check.faceSizes[k]) {
        throw RuntimeFailure("tinyobjloader's faces do not match the OBJ's 'f' lines (face " +
                             std::to_string(k + 1) + ")");
      }
      ScenePolygon polygon;
      polygon.sourceLine = check.faceLines[k];
      polygon.object = shape.name;  // the last `o` or `g` name before the face
      polygon.material = shape.mesh.material_ids[f];
      if (polygon.material >= materialCount) {
        throw RuntimeFailure("tinyobjloader gave the face at line " +
                             std::to_string(polygon.sourceLine) + " an unknown material id");
      }
      for (int v = 0; v < size; ++v) {
        polygon.vertices.push_back(shape.mesh.indices[offset + v].vertex_index);
      }
      // A face has UVs when every corner names a `vt` (OBJ allows "f 1/1 2//1 3": such a face
      // has none, and a bake into the scene's UVs reports it).
      bool allCorners = true;
      for (int v = 0; v < size; ++v)
        allCorners &= shape.mesh.indices[offset + v].texcoord_index >= 0;
      if (allCorners) {
        for (int v = 0; v < size; ++v) {
          const int t = shape.mesh.indices[offset + v].texcoord_index;
          if (2 * static_cast<std::size_t>(t) + 1 >= texcoords.size()) {
            throw RuntimeFailure("tinyobjloader gave the face at line " +
                                 std::to_string(polygon.sourceLine) +
                                 " a texture coordinate out of range");
          }
          polygon.uvs.emplace_back(texcoords[2 * t], texcoords[2 * t + 1]);
        }
      }
      offset += size;
      polygons.push_back(std::move(polygon));
    }
  }
  if (polygons.size() != check.faceLines.size()) {
    throw RuntimeFailure("tinyobjloader read " + std::to_string(polygons.size()) +
                         " faces, the OBJ has " + std::to_string(check.faceLines.size()));
  }
  return polygons;
}

}  // namespace

Scene loadObjScene(const std::string& objPath, UnreadableTextures unreadable) {
  const ObjLineCheck check = checkObjFile(objPath);

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // polygons stay whole: each becomes one patch
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(check.objText, check.mtlText, config)) {
    throw InputError(objPath, 0, "tinyobjloader could not read the file: " + reader.Error());
  }
  if (!reader.Warning().empty()) logDebug(objPath + ": tinyobjloader: " + reader.Warning());

  Scene scene;
  scene.sourcePath = objPath;
  scene.positions = readPositions(reader.GetAttrib(), check, objPath);
  if (static_cast<long>(reader.GetAttrib().texcoords.size() / 2) != check.texcoordCount) {
    throw RuntimeFailure("tinyobjloader read " +
                         std::to_string(reader.GetAttrib().texcoords.size() / 2) +
                         " texture coordinates, expected " + std::to_string(check.texcoordCount));
  }

  // tinyobjloader numbers materials in definition order, as the line check does; it may append
  // unnamed ones (an empty library), which nothing can refer to.
  const std::vector<tinyobj::material_t>& loaded = reader.GetMaterials();
  if (loaded.size() < check.materials.size()) {
    throw RuntimeFailure("tinyobjloader read " + std::to_string(loaded.size()) +
                         " materials, the MTL libraries define " +
                         std::to_string(check.materials.size()));
  }
  ObjTextureLoader textureLoader(&scene.textures, unreadable, &scene.textureFallbacks);
  for (std::size_t i = 0; i < check.materials.size(); ++i) {
    scene.materials.push_back(convertMaterial(loaded[i], check.materials[i]));
    attachTextures(scene.materials.back(), check.materials[i], textureLoader, scene.textures);
  }

  const int defaultId = static_cast<int>(scene.materials.size());
  std::vector<int> degenerateLines, defaultLines, untexturedLines;
  const double diagonal2 = squaredDiagonal(scene.positions);
  for (ScenePolygon& polygon : readPolygons(reader.GetShapes(), reader.GetAttrib().texcoords, check,
                                            static_cast<int>(scene.materials.size()))) {
    for (int v : polygon.vertices) {
      if (v < 0 || v >= static_cast<int>(scene.positions.size())) {
        throw RuntimeFailure("tinyobjloader gave the face at line " +
                             std::to_string(polygon.sourceLine) + " a vertex out of range");
      }
    }
    if (isDegenerate(polygon.vertices, scene.positions, diagonal2)) {
      degenerateLines.push_back(polygon.sourceLine);
      continue;
    }
    if (polygon.material < 0) {
      polygon.material = defaultId;
      defaultLines.push_back(polygon.sourceLine);
    } else {
      const Material& material = scene.materials[polygon.material];
      const bool textured = material.diffuseTexture >= 0 || material.emissionTexture >= 0 ||
                            material.alphaTexture >= 0;
      if (textured && polygon.uvs.empty()) untexturedLines.push_back(polygon.sourceLine);
    }
    scene.polygons.push_back(std::move(polygon));
  }

  scene.skippedDegenerateFaces = static_cast<int>(degenerateLines.size());
  if (!degenerateLines.empty()) {
    logWarning(objPath + ": skipped " + std::to_string(degenerateLines.size()) +
               " degenerate face(s) with repeated vertices or zero area (line " +
               lineList(degenerateLines) + ")");
  }
  if (!untexturedLines.empty()) {
    // A texture needs coordinates to be looked up; without them the material's factors (Kd, Ke,
    // opaque) are all that is known, which is still the material the face asked for.
    logWarning(objPath + ": " + std::to_string(untexturedLines.size()) +
               " face(s) with a textured material have no texture coordinates ('vt') (line " +
               lineList(untexturedLines) + "); they use the material's Kd/Ke alone");
  }
  if (!defaultLines.empty()) {
    scene.materials.push_back(defaultMaterial(objPath));
    scene.usedDefaultMaterial = true;
    logWarning(objPath + ": " + std::to_string(defaultLines.size()) +
               " face(s) have no 'usemtl' (line " + lineList(defaultLines) +
               "); using material 'default', grey with Kd 0.5");
  }
  logInfo("loaded " + objPath + ": " + std::to_string(scene.positions.size()) + " vertices, " +
          std::to_string(scene.polygons.size()) + " polygons, " +
          std::to_string(scene.materials.size()) + " materials, " +
          std::to_string(scene.emitterCount()) + " emitting polygons" +
          (scene.textures.empty() ? std::string()
                                  : ", " + std::to_string(scene.textures.size()) + " textures") +
          (scene.polygonsWithUvs()
               ? ", " + std::to_string(scene.polygonsWithUvs()) + " with texture coordinates"
               : std::string()));
  return scene;
}

}  // namespace rad
