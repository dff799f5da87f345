#pragma once

#include <Eigen/Core>
#include <mutex>
#include <vector>

#include "radiosity/core/rgb.h"

namespace rad {

struct Texture;

// Radiance at infinity over the whole sphere of directions, held as a latitude-longitude
// (equirectangular) image: the environment light of a lights file, and the CIE clear sky's
// formula tabulated for sampling (lights.h). Piecewise constant: every direction inside a texel
// sees that texel's value, so the sampling density below is exactly proportional to luminance.
//
// Orientation: Blender's world convention (Cycles' direction_to_equirectangular), so an HDRI looks
// as it does there. The top row is the zenith `up`, the bottom row the nadir, the rows uniform in
// the zenith angle θ = π t (t down from the top edge). Across, u = 0.5 − φ/(2π) with the azimuth
// φ = atan2(d·side, d·centre): the image's centre column (u = 0.5) looks along `centre`, the
// quarter column (u = 0.25) along `side` = up × centre, the edges (u = 0, 1) along −centre.
// `centre` is +x projected onto the horizon (+y projected when `up` is ±x). With Blender's Z up
// that is Blender's own frame (centre +X, quarter column +Y); with `up` +y it is a Blender scene
// exported Y-up (glTF, OBJ: centre +x, quarter column −z).
class EnvironmentMap {
 public:
  // `radiance`: width × height values in W·m⁻²·sr⁻¹, rows top first. `up`: unit.
  EnvironmentMap(int width, int height, std::vector<Rgb> radiance, const Eigen::Vector3d& up);
  // A decoded image's RGB (linear values, alpha ignored) times `scale`.
  static std::vector<Rgb> scaledTexels(const Texture& image, double scale);

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<Rgb>& texels() const { return radiance_; }
  const Eigen::Vector3d& up() const { return up_; }

  // The image position (u across, t down from the top edge, both in [0, 1)) of a unit direction,
  // and back.
  Eigen::Vector2d imagePosition(const Eigen::Vector3d& direction) const;
  Eigen::Vector3d direction(double u, double t) const;
  // The solid angle of one texel of row y: (2π / width)(cos θ_top − cos θ_bottom).
  double texelSolidAngle(int y) const;

  // The radiance along a unit direction: its texel's value.
  Rgb radiance(const Eigen::Vector3d& direction) const;

  // Importance sampling by luminance: a texel with probability ∝ luminance × its solid angle
  // (rows by the marginal distribution, then a column by the row's conditional one), then a
  // direction uniform in solid angle inside it (φ uniform, cos θ uniform between the row's
  // edges). The density in solid angle is luminance(texel) / Σ luminance × Ω over the map: the
  // continuous form of the piecewise-constant pdf_uv / (2π² sin θ). The point (u1, u2) of the
  // unit square keeps its stratification (each coordinate is remapped inside the chosen bin).
  // A black map has no density: `pdf` 0 and any direction.
  Eigen::Vector3d sample(double u1, double u2, double& pdf) const;
  double pdf(const Eigen::Vector3d& direction) const;

  // The irradiance on a plane of unit normal `n`, unshadowed: ∫ L max(0, n·ω) dω over the whole
  // sphere, from a table over normals (64 azimuths × 33 zenith angles, bilinear between them)
  // that sums 128 × 64 blocks (groups of texels, or parts of one in a smaller map) as point
  // sources at their luminance-weighted mean direction. Built on first use (the local model
  // `direct` is its only user).
  Rgb irradiance(const Eigen::Vector3d& n) const;

 private:
  int texelIndex(const Eigen::Vector3d& direction) const;
  void buildIrradianceTable() const;

  int width_, height_;
  std::vector<Rgb> radiance_;
  Eigen::Vector3d up_, centre_, side_;
  std::vector<double> rowCdf_;     // height + 1 values, 0 … 1
  std::vector<double> columnCdf_;  // per row, width + 1 values, 0 … 1
  double luminanceIntegral_ = 0;   // Σ luminance × Ω
  mutable std::once_flag tableOnce_;
  mutable std::vector<Rgb> irradianceTable_;
};

}  // namespace rad
