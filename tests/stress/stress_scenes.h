#pragma once

// Scenes for the stability stress suite, written as OBJ + MTL so that they go through the same
// loader and validation as a user's file.
#include <unistd.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace rad::testing {

// Accumulates polygons and writes them as one OBJ with its MTL.
class ObjWriter {
 public:
  void material(const std::string& name, double kd, double ke) {
    mtl_ << "newmtl " << name << "\nKd " << kd << ' ' << kd << ' ' << kd << "\nKe " << ke << ' '
         << ke << ' ' << ke << "\n";
  }
  // A polygon, counter-clockwise seen from its front.
  void polygon(const std::string& material, const std::vector<Eigen::Vector3d>& corners) {
    obj_ << "usemtl " << material << "\n";
    for (const Eigen::Vector3d& p : corners)
      obj_ << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << "\n";
    obj_ << "f";
    for (size_t k = 0; k < corners.size(); ++k) obj_ << ' ' << vertices_ + 1 + static_cast<int>(k);
    obj_ << "\n";
    vertices_ += static_cast<int>(corners.size());
  }
  // An axis-aligned box [lo, hi]: faces outward (a solid) or inward (a room).
  void box(const std::string& material, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
           bool inward) {
    const auto c = [&](int i) {
      return Eigen::Vector3d(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                             i & 4 ? hi.z() : lo.z());
    };
    // Outward faces, counter-clockwise from outside.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
      std::vector<Eigen::Vector3d> q = {c(f[0]), c(f[1]), c(f[2]), c(f[3])};
      if (inward) std::reverse(q.begin(), q.end());
      polygon(material, q);
    }
  }
  // Writes NAME.obj and NAME.mtl into a fresh temporary folder and returns the OBJ path.
  std::string write(const std::string& name) const {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("radiosity_stress_" + name + "_" + std::to_string(getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / (name + ".mtl")) << mtl_.str();
    std::ofstream(dir / (name + ".obj")) << std::setprecision(17) << "mtllib " << name << ".mtl\n"
                                         << obj_.str();
    return (dir / (name + ".obj")).string();
  }

  ObjWriter() { obj_.precision(17); }

 private:
  std::ostringstream obj_, mtl_;
  int vertices_ = 0;
};

// A closed unit room (every surface reflectance rho) holding everything that strains the
// numerics at once: a thin plate whose four sides are slivers of aspect ratio 1e6, a decal
// coincident and coplanar with a wall, a sliver triangle lying on the floor, a tiny emitter of
// 1e-6 of the scene's area, and two emitters whose radiance differs by a factor of 1e6.
// Closed and without reachable back faces, so every hemisphere row sums to 1.
inline std::string writeHostileRoom(double rho) {
  ObjWriter w;
  w.material("wall", rho, 0);
  w.material("light", rho, 1);
  w.material("dim", rho, 1e-6);
  w.material("tiny", rho, 10);
  w.box("wall", {0, 0, 0}, {1, 1, 1}, true);
  using V = Eigen::Vector3d;
  // Ceiling light, coincident with the ceiling (z = 1, facing down).
  w.polygon("light", {V(0.4, 0.4, 1), V(0.4, 0.6, 1), V(0.6, 0.6, 1), V(0.6, 0.4, 1)});
  // Emitter 1e6 times dimmer on the wall x = 0 (facing +x).
  w.polygon("dim", {V(0, 0.4, 0.4), V(0, 0.6, 0.4), V(0, 0.6, 0.6), V(0, 0.4, 0.6)});
  // Tiny emitter on the floor (z = 0, facing up): area 6e-6 = 1e-6 of the room's 6 m².
  const double s = std::sqrt(6e-6);
  w.polygon("tiny",
            {V(0.7, 0.7, 0), V(0.7 + s, 0.7, 0), V(0.7 + s, 0.7 + s, 0), V(0.7, 0.7 + s, 0)});
  // Sliver triangle on the floor: 0.6 long, 6e-7 high.
  w.polygon("wall", {V(0.2, 0.2, 0), V(0.8, 0.2, 0), V(0.5, 0.2 + 6e-7, 0)});
  // Decal: a duplicate of part of the wall y = 0 (facing +y).
  w.polygon("wall", {V(0.2, 0, 0.2), V(0.2, 0, 0.8), V(0.8, 0, 0.8), V(0.8, 0, 0.2)});
  // Thin plate, 0.5 × 0.5 × 5e-7: its sides are 0.5 × 5e-7 slivers.
  w.box("wall", {0.25, 0.25, 0.5}, {0.75, 0.75, 0.5 + 5e-7}, false);
  return w.write("hostile_room");
}

}  // namespace rad::testing
