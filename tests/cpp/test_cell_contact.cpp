// Cell model (FFT + CG) against Hertz point contact (known_values.md), the direct convolution,
// grid convergence and warm start.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kegel/core/cell_contact.hpp"

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kE = 210e9 / 0.91;  // steel on steel

struct Hertz {
  double R, Q, a, p0, delta;
  Hertz(double R_, double Q_) : R(R_), Q(Q_) {
    a = std::cbrt(3 * Q * R / (2 * kE));
    p0 = 3 * Q / (2 * kPi * a * a);
    delta = a * a / R;
  }
};

// Sphere of radius R on a flat: gap r^2 / (2R) on an n x n grid over a window of side w.
std::vector<double> sphere_gap(int n, double w, double R) {
  std::vector<double> h(n * n);
  const double d = w / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5 - 0.5 * n) * d, y = (j + 0.5 - 0.5 * n) * d;
      h[i * n + j] = (x * x + y * y) / (2 * R);
    }
  return h;
}

struct Solved {
  double p0, a, delta;
  int iterations;
};

Solved solve(int n, double window_over_a, const Hertz& hz, kegel::CellContactData* keep = nullptr) {
  const double w = window_over_a * hz.a, d = w / n;
  kegel::CellContactModel model(n, n, d, d, kE);
  kegel::CellContactData data(model);
  const auto h = sphere_gap(n, w, hz.R);
  kegel::CellContactSettings s;
  s.tolerance = 1e-10;
  EXPECT_EQ(kegel::solve_cell_contact(model, data, h.data(), hz.Q, s), 0);
  double pmax = 0.0;
  int nc = 0;
  for (double p : data.pressure_Pa) {
    pmax = std::max(pmax, p);
    nc += p > 0.0;
  }
  (void)keep;
  return {pmax, std::sqrt(nc * d * d / kPi), data.approach_m, data.iterations};
}
}  // namespace

TEST(CellContact, LoveSelfInfluenceByHand) {
  // centre of a uniformly loaded square of side 2a: integral of 1/r = 8 a asinh(1)
  EXPECT_NEAR(kegel::love_rectangle_integral(0, 0, 1.0, 1.0), 8 * std::asinh(1.0), 1e-14);
  // far away the rectangle acts like a point force: area / distance
  EXPECT_NEAR(kegel::love_rectangle_integral(100.0, 0.0, 0.5, 0.5), 1.0 / 100.0, 1e-7);
  // symmetric in x and y
  EXPECT_DOUBLE_EQ(kegel::love_rectangle_integral(3.0, 2.0, 0.5, 0.7),
                   kegel::love_rectangle_integral(-3.0, -2.0, 0.5, 0.7));
}

TEST(CellContact, FftConvolutionEqualsDirectSum) {
  const int nx = 7, ny = 5;
  kegel::CellContactModel m(nx, ny, 1e-5, 2e-5, kE);
  kegel::CellContactData d(m);
  std::vector<double> p(nx * ny), u(nx * ny);
  for (int k = 0; k < nx * ny; ++k) p[k] = 1e8 * (1 + std::sin(0.7 * k));
  d.convolve(p.data(), u.data());
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      double ref = 0.0;
      for (int k = 0; k < nx; ++k)
        for (int l = 0; l < ny; ++l) ref += m.influence(i - k, j - l) * p[k * ny + l];
      EXPECT_NEAR(u[i * ny + j], ref, 1e-12 * std::abs(ref));
    }
}

TEST(CellContact, MatchesHertzAt64x64) {
  const Hertz hz(0.01, 100.0);
  const auto s = solve(64, 3.0, hz);
  EXPECT_NEAR(s.p0, hz.p0, 0.02 * hz.p0);
  EXPECT_NEAR(s.a, hz.a, 0.02 * hz.a);
  EXPECT_NEAR(s.delta, hz.delta, 0.01 * hz.delta);
}

TEST(CellContact, ConvergesWithCellCount) {
  const Hertz hz(0.01, 100.0);
  double last = 1.0;
  for (int n : {16, 32, 64}) {
    const auto s = solve(n, 3.0, hz);
    const double err = std::abs(s.delta / hz.delta - 1.0);
    EXPECT_LT(err, last) << n;
    last = err;
  }
  EXPECT_LT(last, 0.01);
}

TEST(CellContact, WarmStartNeedsFewerIterations) {
  const Hertz hz(0.01, 100.0);
  const int n = 32;
  const double w = 3.0 * hz.a, d = w / n;
  kegel::CellContactModel model(n, n, d, d, kE);
  kegel::CellContactData data(model);
  const auto h = sphere_gap(n, w, hz.R);
  ASSERT_EQ(kegel::solve_cell_contact(model, data, h.data(), hz.Q), 0);
  const int cold = data.iterations;
  ASSERT_EQ(kegel::solve_cell_contact(model, data, h.data(), 1.02 * hz.Q), 0);  // next time step
  EXPECT_LT(data.iterations, cold);
  // the answer does not depend on the start
  kegel::CellContactData fresh(model);
  ASSERT_EQ(kegel::solve_cell_contact(model, fresh, h.data(), 1.02 * hz.Q), 0);
  EXPECT_NEAR(fresh.approach_m, data.approach_m, 1e-6 * data.approach_m);
}

TEST(CellContact, LoadBalanceAndComplementarity) {
  const Hertz hz(0.01, 50.0);
  const int n = 32;
  const double w = 3.0 * hz.a, d = w / n;
  kegel::CellContactModel model(n, n, d, d, kE);
  kegel::CellContactData data(model);
  auto h = sphere_gap(n, w, hz.R);
  for (double& v : h) v += 1e-6;  // an offset only shifts the approach
  ASSERT_EQ(kegel::solve_cell_contact(model, data, h.data(), hz.Q), 0);
  double P = 0.0;
  for (int k = 0; k < n * n; ++k) {
    P += data.pressure_Pa[k] * d * d;
    const double gap = h[k] + data.displacement_m[k] - data.approach_m;
    if (data.pressure_Pa[k] > 0) EXPECT_NEAR(gap, 0.0, 1e-4 * hz.delta);
    else EXPECT_GT(gap, -1e-4 * hz.delta);
  }
  EXPECT_NEAR(P, hz.Q, 1e-9 * hz.Q);
}

TEST(CellContact, InvalidInput) {
  EXPECT_THROW(kegel::CellContactModel(1, 8, 1e-5, 1e-5, kE), std::invalid_argument);
  EXPECT_THROW(kegel::CellContactModel(8, 8, -1e-5, 1e-5, kE), std::invalid_argument);
  kegel::CellContactModel m(4, 4, 1e-5, 1e-5, kE);
  kegel::CellContactData d(m);
  std::vector<double> h(16, 0.0);
  EXPECT_EQ(kegel::solve_cell_contact(m, d, h.data(), -1.0), -1);
  h[3] = NAN;
  EXPECT_EQ(kegel::solve_cell_contact(m, d, h.data(), 1.0), -1);
}
