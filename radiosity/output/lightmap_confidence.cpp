#include "radiosity/output/lightmap_confidence.h"

#include <algorithm>
#include <cstdio>

#include "meshing/adaptive_refinement.h"
#include "radiosity/core/check.h"

namespace rad {

std::vector<Rgb> displayedError(const PatchMesh& mesh, const std::vector<Rgb>& perElement,
                                const std::vector<std::array<Rgb, 3>>& atPoints) {
  const int n = mesh.elementCount();
  std::vector<Rgb> error(n);
  for (int c = 0; c < 3; ++c) {
    std::vector<double> channel;
    if (atPoints.empty()) {
      RAD_CHECK_EQ(perElement.size(), static_cast<size_t>(n));
      channel.resize(n);
      for (int e = 0; e < n; ++e) channel[e] = perElement[e][c];
      channel = displayedVariation(mesh, channel);
    } else {
      RAD_CHECK_EQ(atPoints.size(), static_cast<size_t>(n));
      std::vector<std::array<double, 3>> points(n);
      for (int e = 0; e < n; ++e)
        for (int k = 0; k < 3; ++k) points[e][k] = atPoints[e][k][c];
      channel = displayedPointError(mesh, points);
    }
    for (int e = 0; e < n; ++e) error[e][c] = channel[e];
  }
  return error;
}

std::vector<float> errorChannel(const Lightmap& error) {
  std::vector<float> channel(error.radiance.pixels.size());
  for (size_t i = 0; i < channel.size(); ++i)
    channel[i] = static_cast<float>(error.radiance.pixels[i].luminance());
  return channel;
}

ConfidenceSummary summariseConfidence(const std::vector<Lightmap>& values,
                                      const std::vector<Lightmap>& errors) {
  RAD_CHECK_EQ(values.size(), errors.size());
  std::vector<double> relative;
  for (size_t page = 0; page < values.size(); ++page) {
    const Lightmap& v = values[page];
    RAD_CHECK_EQ(v.radiance.pixels.size(), errors[page].radiance.pixels.size());
    for (size_t i = 0; i < v.state.size(); ++i) {
      const double value = v.radiance.pixels[i].luminance();
      if (v.state[i] != TexelState::Covered || !(value > 0)) continue;
      relative.push_back(errors[page].radiance.pixels[i].luminance() / value);
    }
  }
  ConfidenceSummary s;
  s.texels = relative.size();
  if (relative.empty()) return s;
  std::sort(relative.begin(), relative.end());
  auto quantile = [&](double q) {
    return relative[std::min(relative.size() - 1, static_cast<size_t>(q * relative.size()))];
  };
  s.medianRelative = quantile(0.5);
  s.p95Relative = quantile(0.95);
  const auto above = relative.end() - std::upper_bound(relative.begin(), relative.end(), 0.1);
  s.fractionAbove10Percent = static_cast<double>(above) / relative.size();
  return s;
}

std::string describeConfidence(const ConfidenceSummary& s) {
  char line[160];
  std::snprintf(line, sizeof line,
                "median relative error %.1f%%, 95th percentile %.1f%%, %.1f%% of covered texels "
                "above 10%%",
                100 * s.medianRelative, 100 * s.p95Relative, 100 * s.fractionAbove10Percent);
  return line;
}

}  // namespace rad
