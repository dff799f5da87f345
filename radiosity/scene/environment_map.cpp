#include "radiosity/scene/environment_map.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "radiosity/core/check.h"
#include "radiosity/scene/texture.h"

namespace rad {
namespace {

constexpr int kTableAzimuths = 64, kTableZeniths = 33;  // zenith nodes include both poles
constexpr int kBlockColumns = 128, kBlockRows = 64;

// Turns weights into a cumulative distribution (n + 1 values from 0 to exactly 1); returns the sum
// (0: all zero, the cdf left at 0).
double cumulate(const std::vector<double>& weights, double* cdf) {
  double sum = 0;
  cdf[0] = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) cdf[i + 1] = sum += weights[i];
  if (!(sum > 0)) return 0;
  for (std::size_t i = 1; i <= weights.size(); ++i) cdf[i] /= sum;
  cdf[weights.size()] = 1;
  return sum;
}

// The bin i of a cdf with cdf[i] ≤ u < cdf[i + 1] (never an empty one), and u's place inside it.
int findBin(const double* cdf, int n, double u, double& within) {
  const int i =
      std::clamp(static_cast<int>(std::upper_bound(cdf, cdf + n + 1, u) - cdf) - 1, 0, n - 1);
  const double width = cdf[i + 1] - cdf[i];
  within = width > 0 ? std::clamp((u - cdf[i]) / width, 0.0, 1.0) : 0.5;
  return i;
}

}  // namespace

EnvironmentMap::EnvironmentMap(int width, int height, std::vector<Rgb> radiance,
                               const Eigen::Vector3d& up)
    : width_(width), height_(height), radiance_(std::move(radiance)), up_(up.normalized()) {
  RAD_CHECK(width_ > 0 && height_ > 0);
  RAD_CHECK_EQ(radiance_.size(), static_cast<std::size_t>(width_) * height_);
  const Eigen::Vector3d x =
      std::abs(up_.x()) > 0.9999 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  centre_ = (x - x.dot(up_) * up_).normalized();
  side_ = up_.cross(centre_);

  rowCdf_.assign(height_ + 1, 0);
  columnCdf_.assign(static_cast<std::size_t>(height_) * (width_ + 1), 0);
  std::vector<double> rows(height_), columns(width_);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x)
      columns[x] = std::max(0.0, radiance_[static_cast<std::size_t>(y) * width_ + x].luminance());
    rows[y] = cumulate(columns, &columnCdf_[static_cast<std::size_t>(y) * (width_ + 1)]) *
              texelSolidAngle(y);
  }
  luminanceIntegral_ = cumulate(rows, rowCdf_.data());
}

std::vector<Rgb> EnvironmentMap::scaledTexels(const Texture& image, double scale) {
  std::vector<Rgb> out(static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = Rgb(image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]) * scale;
  return out;
}

Eigen::Vector2d EnvironmentMap::imagePosition(const Eigen::Vector3d& d) const {
  const double phi = std::atan2(d.dot(side_), d.dot(centre_));
  double u = 0.5 - phi / (2 * M_PI);
  if (u >= 1) u -= 1;
  return {std::max(0.0, u), std::acos(std::clamp(d.dot(up_), -1.0, 1.0)) / M_PI};
}

Eigen::Vector3d EnvironmentMap::direction(double u, double t) const {
  const double phi = 2 * M_PI * (0.5 - u), theta = M_PI * t;
  return std::sin(theta) * (std::cos(phi) * centre_ + std::sin(phi) * side_) +
         std::cos(theta) * up_;
}

double EnvironmentMap::texelSolidAngle(int y) const {
  return 2 * M_PI / width_ * (std::cos(M_PI * y / height_) - std::cos(M_PI * (y + 1) / height_));
}

int EnvironmentMap::texelIndex(const Eigen::Vector3d& direction) const {
  const Eigen::Vector2d p = imagePosition(direction);
  const int x = std::min(width_ - 1, static_cast<int>(p.x() * width_));
  const int y = std::min(height_ - 1, static_cast<int>(p.y() * height_));
  return y * width_ + x;
}

Rgb EnvironmentMap::radiance(const Eigen::Vector3d& direction) const {
  return radiance_[texelIndex(direction)];
}

Eigen::Vector3d EnvironmentMap::sample(double u1, double u2, double& pdf) const {
  pdf = 0;
  if (!(luminanceIntegral_ > 0)) return up_;
  double v = 0, w = 0;
  const int y = findBin(rowCdf_.data(), height_, u1, v);
  const int x = findBin(&columnCdf_[static_cast<std::size_t>(y) * (width_ + 1)], width_, u2, w);
  // Uniform in solid angle inside the texel: cos θ uniform between the row's edges.
  const double cosTop = std::cos(M_PI * y / height_),
               cosBottom = std::cos(M_PI * (y + 1) / height_);
  const double cosTheta = std::clamp(cosTop - v * (cosTop - cosBottom), -1.0, 1.0);
  const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
  const double phi = 2 * M_PI * (0.5 - (x + w) / width_);
  pdf = radiance_[static_cast<std::size_t>(y) * width_ + x].luminance() / luminanceIntegral_;
  return (sinTheta * (std::cos(phi) * centre_ + std::sin(phi) * side_) + cosTheta * up_)
      .normalized();
}

double EnvironmentMap::pdf(const Eigen::Vector3d& direction) const {
  if (!(luminanceIntegral_ > 0)) return 0;
  return std::max(0.0, radiance_[texelIndex(direction)].luminance()) / luminanceIntegral_;
}

void EnvironmentMap::buildIrradianceTable() const {
  // Point sources: a large map's texels grouped into blocks, a small map's texels split into
  // cells (so that no source spans much more than a block), each with its power Σ L Ω at its
  // luminance-weighted direction (where a sun's texel lies, not the block's centre).
  const int sx = (kBlockColumns + width_ - 1) / width_, sy = (kBlockRows + height_ - 1) / height_;
  const long long cellsX = static_cast<long long>(width_) * sx,
                  cellsY = static_cast<long long>(height_) * sy;
  const int bw = static_cast<int>(std::min<long long>(cellsX, kBlockColumns));
  const int bh = static_cast<int>(std::min<long long>(cellsY, kBlockRows));
  std::vector<Rgb> power(static_cast<std::size_t>(bw) * bh);
  std::vector<Eigen::Vector3d> weighted(power.size(), Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> centre(power.size(), Eigen::Vector3d::Zero());
  for (long long cy = 0; cy < cellsY; ++cy) {
    const double t0 = static_cast<double>(cy) / cellsY, t1 = static_cast<double>(cy + 1) / cellsY;
    const double omega = 2 * M_PI / cellsX * (std::cos(M_PI * t0) - std::cos(M_PI * t1));
    const std::size_t by = static_cast<std::size_t>(cy * bh / cellsY);
    for (long long cx = 0; cx < cellsX; ++cx) {
      const std::size_t b = by * bw + static_cast<std::size_t>(cx * bw / cellsX);
      const Rgb& l = radiance_[static_cast<std::size_t>(cy / sy) * width_ + (cx / sx)];
      const Eigen::Vector3d d = direction((cx + 0.5) / cellsX, (cy + 0.5) / cellsY);
      power[b] += l * omega;
      weighted[b] += std::max(0.0, l.luminance()) * omega * d;
      centre[b] += omega * d;
    }
  }
  for (std::size_t b = 0; b < power.size(); ++b)
    weighted[b] = weighted[b].norm() > 0 ? weighted[b].normalized() : centre[b].normalized();
  irradianceTable_.assign(static_cast<std::size_t>(kTableAzimuths) * kTableZeniths, Rgb());
  for (int i = 0; i < kTableZeniths; ++i)
    for (int j = 0; j < kTableAzimuths; ++j) {
      const Eigen::Vector3d n = direction(static_cast<double>(j) / kTableAzimuths,
                                          static_cast<double>(i) / (kTableZeniths - 1));
      Rgb sum;
      for (std::size_t b = 0; b < power.size(); ++b) {
        const double c = n.dot(weighted[b]);
        if (c > 0) sum += power[b] * c;
      }
      irradianceTable_[static_cast<std::size_t>(i) * kTableAzimuths + j] = sum;
    }
}

Rgb EnvironmentMap::irradiance(const Eigen::Vector3d& n) const {
  std::call_once(tableOnce_, [this] { buildIrradianceTable(); });
  const Eigen::Vector2d p = imagePosition(n);
  const double fu = p.x() * kTableAzimuths, ft = p.y() * (kTableZeniths - 1);
  const int j = std::min(kTableAzimuths - 1, static_cast<int>(fu));
  const int i = std::min(kTableZeniths - 2, static_cast<int>(ft));
  const double a = fu - j, b = ft - i;
  const auto at = [&](int row, int column) {
    return irradianceTable_[static_cast<std::size_t>(row) * kTableAzimuths +
                            (column % kTableAzimuths)];
  };
  return (at(i, j) * (1 - a) + at(i, j + 1) * a) * (1 - b) +
         (at(i + 1, j) * (1 - a) + at(i + 1, j + 1) * a) * b;
}

}  // namespace rad
