// Fairing of the chordal surface (chordal/chordal_fairing.hpp): a noisy cylinder patch loses its noise, keeps
// its rim and does not shrink.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "chordal/chordal_fairing.hpp"

using namespace hexlayer;

TEST(ChordalFairing, RemovesNoiseKeepsTheRimAndDoesNotShrinkACylinder) {
  // A noisy cylinder patch of radius 10 (angle 0..90°, z 0..10), grid 31 x 11, as quads.
  ChordalSurface s;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(-0.2, 0.2);
  const int na = 31, nz = 11;
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < na; ++i) {
      const double a = M_PI / 2 * i / (na - 1), rim = (i == 0 || i == na - 1 || k == 0 || k == nz - 1);
      const double rr = 10 + (rim ? 0 : noise(random));
      s.vertices.emplace_back(rr * std::cos(a), rr * std::sin(a), k * 1.0);
    }
  for (int k = 0; k + 1 < nz; ++k)
    for (int i = 0; i + 1 < na; ++i)
      s.facets.push_back({k * na + i, k * na + i + 1, (k + 1) * na + i + 1, (k + 1) * na + i});
  const std::vector<Vec3> before = s.vertices;
  auto radialError = [&](const std::vector<Vec3>& v) {  // root mean square distance to the cylinder
    double sum = 0;
    for (const Vec3& p : v) sum += std::pow(std::hypot(p.x(), p.y()) - 10, 2);
    return std::sqrt(sum / v.size());
  };
  fairChordalSurface(s, 10);
  EXPECT_GT(radialError(before), 0.09);
  EXPECT_LT(radialError(s.vertices), 0.45 * radialError(before)) << "most of the noise is gone";
  double meanRadius = 0;
  for (const Vec3& p : s.vertices) meanRadius += std::hypot(p.x(), p.y()) / s.vertices.size();
  EXPECT_NEAR(meanRadius, 10, 0.01) << "Taubin's smoothing does not shrink the surface";
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < na; ++i)
      if (i == 0 || i == na - 1 || k == 0 || k == nz - 1) EXPECT_EQ(s.vertices[k * na + i], before[k * na + i]);
}
