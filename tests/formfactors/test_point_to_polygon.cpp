// The analytic point-to-polygon form factor against Howell's catalogue (REFERENCES.md).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "radiosity/core/rng.h"
#include "radiosity/formfactors/hemisphere_sampling.h"
#include "radiosity/formfactors/point_to_polygon.h"
#include "tests/support/analytic_form_factors.h"

namespace rad {
namespace {

using Polygon = std::vector<Eigen::Vector3d>;

// A disc of radius r in the plane z = h, facing −z (towards the origin), as an m-gon of the same
// area (so the polygon's own discretisation costs nothing at first order).
Polygon discFacingDown(double r, double h, int m) {
  const double equalArea = r * std::sqrt(2 * M_PI / (m * std::sin(2 * M_PI / m)));
  Polygon p;
  for (int k = m - 1; k >= 0; --k) {  // clockwise seen from above = counter-clockwise from below
    const double a = 2 * M_PI * k / m;
    p.emplace_back(equalArea * std::cos(a), equalArea * std::sin(a), h);
  }
  return p;
}

// Area average of the point value over a rectangle [0,a]×[0,b] (z = 0, normal +z) with an n×n
// Gauss–Legendre rule (5 points per axis, composite over `cells` cells).
template <class F>
double averageOverRectangle(double a, double b, int cells, F pointValue) {
  const double x5[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                        0.9061798459386640};
  const double w5[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                        0.4786286704993665, 0.2369268850561891};
  double sum = 0;
  for (int ci = 0; ci < cells; ++ci)
    for (int cj = 0; cj < cells; ++cj)
      for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
          const double x = a * (ci + 0.5 + 0.5 * x5[i]) / cells;
          const double y = b * (cj + 0.5 + 0.5 * x5[j]) / cells;
          sum += w5[i] * w5[j] / 4 * pointValue(x, y);
        }
  return sum / (cells * cells);
}

TEST(PointToPolygon, PointBelowTheCentreOfASquare) {
  // 2×2 square at height 1, facing down, seen from the origin looking up.
  const Polygon square = {{-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}};
  EXPECT_NEAR(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, square), 0.554126, 0.554126 * 1e-5);
}

TEST(PointToPolygon, DifferentialElementToCoaxialDisc) {
  for (const double h : {0.25, 1.0, 3.0}) {
    const double exact = 1.0 / (1.0 + h * h);  // R = 1
    EXPECT_NEAR(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, discFacingDown(1, h, 720)), exact,
                exact * 1e-4)
        << "h = " << h;
  }
}

TEST(PointToPolygon, BackOfTheSourceSeesNothing) {
  const Polygon facingUp = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  EXPECT_EQ(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, facingUp), 0.0);
  // And a receiver facing away sees nothing of a source above it.
  const Polygon facingDown = {{-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}};
  EXPECT_EQ(pointToPolygonFormFactor({0, 0, 0}, {0, 0, -1}, facingDown), 0.0);
}

TEST(PointToPolygon, AreaIntegralsMatchHowellWithinHalfAPercent) {
  // Parallel squares at distance 1 and the (1, 1.5, 0.5) rectangles.
  for (const auto& [a, b, c] : {std::tuple{1.0, 1.0, 1.0}, std::tuple{1.0, 1.5, 0.5}}) {
    const Polygon top = {{0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c}};
    const double f = averageOverRectangle(a, b, 4, [&](double x, double y) {
      return pointToPolygonFormFactor({x, y, 0}, {0, 0, 1}, top);
    });
    const double exact = reference::parallelRectangles(a, b, c);
    EXPECT_NEAR(f, exact, 0.005 * exact) << a << " " << b << " " << c;
  }
  // Perpendicular unit squares sharing the x axis edge: floor y in [0,1] facing +z... here the
  // receiver is z = 0 (x, y in [0,1]), the source the wall y = 0, z in [0,1], facing +y.
  const Polygon wall = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
  const double f = averageOverRectangle(1, 1, 8, [&](double x, double y) {
    return pointToPolygonFormFactor({x, y, 0}, {0, 0, 1}, wall);
  });
  EXPECT_NEAR(f, reference::perpendicularRectangles(1, 1, 1), 0.005 * 0.200044);
}

TEST(PointToPolygon, CoaxialDiscs) {
  // r1 = r2 = L = 1: F = 0.381966. Integrate over disc 1 in polar coordinates (Gauss in r², uniform
  // in φ).
  const Polygon upper = discFacingDown(1, 1, 720);
  const double x5[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                        0.9061798459386640};
  const double w5[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                        0.4786286704993665, 0.2369268850561891};
  double f = 0;
  for (int i = 0; i < 5; ++i) {
    const double s = 0.5 + 0.5 * x5[i];  // s = r², uniform in area
    // Coaxial: the value depends on r only.
    f += 0.5 * w5[i] * pointToPolygonFormFactor({std::sqrt(s), 0, 0}, {0, 0, 1}, upper);
  }
  EXPECT_NEAR(f, 0.381966, 0.005 * 0.381966);
}

TEST(PointToPolygon, PointOnTheSharedEdgeTakesTheLimitFromInside) {
  const Polygon wall = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
  const Eigen::Vector3d n(0, 0, 1);
  const double onEdge = pointToPolygonFormFactor({0.5, 0, 0}, n, wall);
  const double inside = pointToPolygonFormFactor({0.5, 1e-7, 0}, n, wall);
  EXPECT_TRUE(std::isfinite(onEdge));
  EXPECT_NEAR(onEdge, inside, 1e-6);
  // At its foot any wall fills the whole half of the hemisphere on its side: F → 1/2.
  EXPECT_NEAR(onEdge, 0.5, 1e-9);
  // Coplanar neighbours exchange nothing, even when p sits on the shared edge.
  const Polygon coplanar = {{0, 0, 0}, {1, 0, 0}, {1, -1, 0}, {0, -1, 0}};
  EXPECT_EQ(pointToPolygonFormFactor({0.5, 0, 0}, n, coplanar), 0.0);
  EXPECT_NEAR(pointToPolygonFormFactor({0.5, 0.3, 0}, n, coplanar), 0.0, 1e-12);
}

TEST(PointToPolygon, SourceCrossingTheHorizonIsClipped) {
  // A tilted square half below p's tangent plane: compare with a Monte Carlo estimate that shoots
  // cosine-weighted rays from p and counts hits on the polygon (an independent method).
  const Polygon tilted = {{-1, 2, -1}, {1, 2, -1}, {1, 1, 1}, {-1, 1, 1}};  // faces roughly −y,+z
  const Eigen::Vector3d p(0, 0, 0), n(0, 0, 1);
  const double analytic = pointToPolygonFormFactor(p, n, tilted);
  const Eigen::Vector3d a = tilted[0], e1 = tilted[1] - a, e2 = tilted[3] - a;
  const Eigen::Vector3d normal = e1.cross(e2);
  Rng rng(12345);
  const int rays = 400000;
  int hits = 0;
  for (int k = 0; k < rays; ++k) {
    const Eigen::Vector3d d = cosineWeightedDirection(rng.uniform(), rng.uniform());
    const double denom = normal.dot(d);
    if (denom >= 0) continue;  // parallel or hitting the back
    const double t = normal.dot(a - p) / denom;
    if (t <= 0) continue;
    const Eigen::Vector3d q = p + t * d - a;
    // Parallelogram coordinates.
    const double u = q.dot(e1) / e1.squaredNorm(), v = q.dot(e2) / e2.squaredNorm();
    if (u >= 0 && u <= 1 && v >= 0 && v <= 1) ++hits;
  }
  const double estimate = double(hits) / rays;
  const double sigma = std::sqrt(estimate * (1 - estimate) / rays);
  EXPECT_GT(analytic, 0.01);
  EXPECT_NEAR(analytic, estimate, 4 * sigma);
}

}  // namespace
}  // namespace rad
