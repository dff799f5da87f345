#pragma once

#include <cmath>

namespace rad {

// Neumaier's compensated summation: energy totals over many elements keep full precision.
class CompensatedSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    if (std::fabs(sum_) >= std::fabs(x))
      compensation_ += (sum_ - t) + x;
    else
      compensation_ += (x - t) + sum_;
    sum_ = t;
  }
  CompensatedSum& operator+=(double x) {
    add(x);
    return *this;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0;
  double compensation_ = 0;
};

}  // namespace rad
