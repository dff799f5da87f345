#include "radiosity/pipeline/solve_options.h"

#include <cmath>

#include "radiosity/core/errors.h"
#include "radiosity/pipeline/resource_limits.h"

namespace rad {

const NameTable<FormFactorMethod>& formFactorMethodTable() {
  static const NameTable<FormFactorMethod> table = {{"hemisphere", FormFactorMethod::Hemisphere},
                                                    {"analytic", FormFactorMethod::Analytic}};
  return table;
}

FormFactorMethod parseFormFactorMethod(const std::string& name) {
  return parseName(formFactorMethodTable(), name, "form-factor method");
}

std::string formFactorMethodName(FormFactorMethod method) {
  return nameOf(formFactorMethodTable(), method);
}

void validateSolveOptions(const SolveOptions& options) {
  if (options.raysPerElement < 1) throw InputError("--rays must be at least 1");
  if (options.raysPerElement > kMaxRaysPerElement)
    throw InputError("--rays must be at most " + std::to_string(kMaxRaysPerElement));
  if (options.maxArea < 0 || !std::isfinite(options.maxArea))
    throw InputError("--max-area must be a positive number");
  if (options.elementSize < 0 || !std::isfinite(options.elementSize))
    throw InputError("--element-size must be a positive number");
  if (options.targetElements < 0) throw InputError("--elements must be positive");
  if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
    throw InputError("--tolerance must be a non-negative number");
  if (options.maxIterations < 0) throw InputError("--max-iterations must be non-negative");
  if (options.threads < 0) throw InputError("--threads must be non-negative");
  if (options.shadowRays < 1 || options.shadowRays > 4096)
    throw InputError("--shadow-rays must be between 1 and 4096");
  if (options.receiverPoints != 1 && options.receiverPoints != 3)
    throw InputError("--receiver-points must be 1 or 3");
  if (options.patchArea < 0 || !std::isfinite(options.patchArea))
    throw InputError("--patch-area must be a positive number");
  if (options.refineThreshold < 0 || options.minArea < 0 || options.maxElements < 0 ||
      options.refinePasses < 0)
    throw InputError(
        "--refine-threshold, --min-area, --max-elements and --refine-passes must be non-negative");
  if (options.refineThreshold > 0 && (options.formFactors != FormFactorMethod::Analytic ||
                                      options.solver != SolverKind::Progressive))
    throw InputError(
        "adaptive refinement (--refine-threshold) needs --form-factors analytic and "
        "--solver progressive: patches keep shooting while the elements are refined");
  if (options.lightGroups && options.refineThreshold > 0)
    throw InputError(
        "--light-groups with adaptive refinement (--refine-threshold): refinement would fit the "
        "mesh to one mix of the groups, while the layers are meant to be mixed at will; use a "
        "finer uniform mesh (--element-size) instead");
  if (options.keepFactors && (options.formFactors != FormFactorMethod::Hemisphere ||
                              options.refineThreshold > 0 || options.lightGroups))
    throw InputError(
        "--keep-factors keeps hemisphere rows over a uniform mesh: not with --form-factors "
        "analytic, adaptive refinement or light groups");
  if (!(options.linkEpsilon > 0) || !std::isfinite(options.linkEpsilon))
    throw InputError("--link-epsilon must be a positive number");
  if (options.solver == SolverKind::Hierarchical &&
      (options.formFactors != FormFactorMethod::Hemisphere || options.lightGroups ||
       options.keepFactors))
    throw InputError(
        "--solver hierarchical casts its own rays per link receiver: not with --form-factors "
        "analytic, --light-groups or --keep-factors");
  if (!(options.timeLimit >= 0) || !std::isfinite(options.timeLimit))
    throw InputError("--time-limit must be a non-negative number of seconds");
  if (options.bounces >= 0 && options.solver != SolverKind::Jacobi)
    throw InputError("--bounces applies to --solver jacobi only");
}

void checkOptionsApply(const SolveOptions& options, const std::set<std::string>& given) {
  const auto unused = [&](const std::string& name, const std::string& why) {
    if (given.count(name)) throw InputError(name + " is not used: " + why);
  };
  const bool analytic = options.formFactors == FormFactorMethod::Analytic;
  const std::string method = "--form-factors " + formFactorMethodName(options.formFactors);
  if (analytic)
    unused("--rays", method +
                         " casts --shadow-rays per receiver point and patch, not "
                         "hemisphere rays per element");
  else
    for (const char* name : {"--patch-area", "--shadow-rays", "--receiver-points"})
      unused(name, method + " casts hemisphere rays per element (--rays); " + name +
                       " applies to --form-factors analytic");
  if (options.maxArea > 0) {
    unused("--elements", "--max-area sets the element size; --elements only derives it");
    unused("--element-size", "--max-area sets the element size");
  }
  if (options.elementSize > 0)
    unused("--elements", "--element-size sets the element size; --elements only derives it");
  if (options.bounces >= 0)
    unused("--tolerance", "--bounces runs exactly that many Jacobi bounces, whatever the residual");
  if (options.solver != SolverKind::Hierarchical)
    unused("--link-epsilon", "it sets the links of --solver hierarchical");
  if (!(options.refineThreshold > 0))
    for (const char* name : {"--min-area", "--max-elements", "--refine-passes"})
      unused(name, std::string(name) +
                       " shapes adaptive refinement, which is off without "
                       "--refine-threshold");
}

}  // namespace rad
