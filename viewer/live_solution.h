#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"

namespace rad {

// One ray of a form-factor row, for drawing: from the element to what it hit (or, for a ray
// that escaped, to a point some way along it).
struct RaySegment {
  Eigen::Vector3d from, to;
  bool hit = false;
};

// A solver the viewer can drive while it shows the solution: the command line builds it (the
// viewer never depends on the solvers), the viewer calls step() and redraws.
class LiveSolution {
 public:
  virtual ~LiveSolution() = default;
  // B per element (W/m²); with the ambient term of progressive shooting when asked and available.
  virtual std::vector<Rgb> radiosity(bool withAmbient) const = 0;
  virtual std::vector<Rgb> unshot() const = 0;  // W per channel, zeros for gathering solvers
  virtual void step() = 0;                      // one shot, sweep or bounce
  virtual void restart() = 0;                   // back to B = E, before the first step
  virtual bool converged() const = 0;           // the tolerance or the iteration budget reached
  virtual int iterations() const = 0;
  // The convergence measure before the first step and after each step since.
  virtual const std::vector<double>& history() const = 0;
  virtual std::string measure() const = 0;
  virtual std::string solverName() const = 0;
  virtual int lastShooter() const = 0;  // -1 before the first shot or for gathering solvers
  // The rays of the element's form-factor row, as the solver computed it.
  virtual std::vector<RaySegment> rowRays(int element) const = 0;
};

}  // namespace rad
