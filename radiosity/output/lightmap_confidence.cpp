#include "radiosity/output/lightmap_confidence.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>

#include "meshing/adaptive_refinement.h"
#include "radiosity/core/check.h"

namespace rad {

std::vector<Rgb> displayedError(const PatchMesh& mesh, const std::vector<Rgb>& perElement,
                                const std::vector<std::array<Rgb, 3>>& atPoints) {
  const int n = mesh.elementCount();
  std::vector<Rgb> error(n);
  // The channels on their own threads: each walks the whole mesh for its corner values.
  tbb::parallel_for(0, 3, [&](int c) {
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
  });
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
  // The quantiles by selection, not a sort of the million texels: the median first, then the
  // 95th percentile among the values above it.
  auto quantile = [&](double q, std::vector<double>::iterator from) {
    const auto at =
        relative.begin() + std::min(relative.size() - 1, static_cast<size_t>(q * relative.size()));
    std::nth_element(from, at, relative.end());
    return at;
  };
  const auto median = quantile(0.5, relative.begin());
  s.medianRelative = *median;
  s.p95Relative = *quantile(0.95, median);
  const auto above =
      std::count_if(relative.begin(), relative.end(), [](double r) { return r > 0.1; });
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
