#include "radiosity/lighting/power_distribution.h"

#include <algorithm>
#include <cmath>

namespace rad {

PowerDistribution::PowerDistribution(const std::vector<double>& weights) {
  for (const double w : weights) {
    total_ += w;
    cumulative_.push_back(total_);
  }
  probability_.resize(weights.size());
  for (size_t k = weights.size(); k-- > 0;) {  // from the end: each needs its predecessor's sum
    probability_[k] = (cumulative_[k] - (k > 0 ? cumulative_[k - 1] : 0.0)) / total_;
    cumulative_[k] /= total_;
  }
  if (!cumulative_.empty()) cumulative_.back() = 1.0;
}

size_t PowerDistribution::pick(double u) const {
  return std::min(static_cast<size_t>(std::upper_bound(cumulative_.begin(), cumulative_.end(), u) -
                                      cumulative_.begin()),
                  cumulative_.size() - 1);
}

double PowerDistribution::rescaled(double u, size_t k) const {
  const double low = k > 0 ? cumulative_[k - 1] : 0.0, width = cumulative_[k] - low;
  return width > 0 ? std::clamp((u - low) / width, 0.0, std::nextafter(1.0, 0.0)) : 0.5;
}

}  // namespace rad
