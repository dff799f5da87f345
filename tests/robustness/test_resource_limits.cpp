// Resource limits decided before any work (issue 9): the form-factor memory estimate, the check
// against available memory, and scene limits (the command-line side: test_absurd_options.cpp).
#include <gtest/gtest.h>

#include <limits>

#include "radiosity/core/errors.h"
#include "radiosity/pipeline/resource_limits.h"

namespace rad {
namespace {

TEST(MemoryEstimate, BoundsRowsByRaysOrElementsAndPatches) {
  // Hemisphere: a row holds at most one entry per ray and per element (12 bytes each).
  EXPECT_EQ(formFactorMemoryEstimate(FormFactorMethod::Hemisphere, 1000, 1000, 64),
            1000u * 64 * 12);
  EXPECT_EQ(formFactorMemoryEstimate(FormFactorMethod::Hemisphere, 100, 100, 1024),
            100u * 100 * 12);
  // Analytic: elements × shooting patches, whatever the ray count.
  EXPECT_EQ(formFactorMemoryEstimate(FormFactorMethod::Analytic, 4000, 500, 1), 4000u * 500 * 12);
  // With 3 receiver points each entry also keeps 3 single-precision point factors.
  EXPECT_EQ(formFactorMemoryEstimate(FormFactorMethod::Analytic, 4000, 500, 1, 3),
            4000u * 500 * 24);
  // No overflow at the element limit with the largest ray count.
  EXPECT_EQ(formFactorMemoryEstimate(FormFactorMethod::Hemisphere, 4000000, 4000000, 1 << 24),
            uint64_t{4000000} * 4000000 * 12);
}

TEST(MemoryEstimate, CheckNamesTheOptionsToChange) {
  EXPECT_NO_THROW(checkFormFactorMemory(100, 200, FormFactorMethod::Hemisphere));
  EXPECT_NO_THROW(
      checkFormFactorMemory(100, 0, FormFactorMethod::Hemisphere));  // unknown: no check
  try {
    checkFormFactorMemory(uint64_t{3} << 30, uint64_t{1} << 30, FormFactorMethod::Hemisphere);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("--elements"), std::string::npos) << text;
    EXPECT_NE(text.find("--rays"), std::string::npos) << text;
    EXPECT_NE(text.find("3 GiB"), std::string::npos) << text;
  }
  try {
    checkFormFactorMemory(uint64_t{3} << 30, uint64_t{1} << 30, FormFactorMethod::Analytic);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--patch-area"), std::string::npos) << e.what();
  }
}

TEST(MemoryEstimate, AvailableMemoryIsReadFromProcMeminfo) {
  const uint64_t available = availableMemoryBytes();
  EXPECT_GT(available, uint64_t{1} << 20);  // this machine has more than a megabyte free
  EXPECT_LT(available, uint64_t{1} << 50);
}

TEST(SceneLimits, CoordinatesBeyondTheLimitAreRejected) {
  Scene scene;
  scene.sourcePath = "far.obj";
  scene.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  scene.polygons.push_back(ScenePolygon{{0, 1, 2}, 0, 3, {}, "", {}, -1});
  EXPECT_NO_THROW(checkSceneLimits(scene));
  scene.positions[1].x() = 2 * kMaxCoordinate;
  EXPECT_THROW(checkSceneLimits(scene), InputError);
  scene.positions[1].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(checkSceneLimits(scene), InputError);
}

}  // namespace
}  // namespace rad
