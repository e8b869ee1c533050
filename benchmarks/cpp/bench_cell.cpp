// Benchmark: cell model (FFT + CG, Polonsky-Keer) of a Hertzian point contact, cold and
// warm-started, at several grid sizes; runtime medians beside the error against the finest
// grid (and against Hertz theory).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "kegel/core/cell_contact.hpp"

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kE = 210e9 / 0.91;
constexpr double kR = 0.01, kQ = 100.0;

struct Row { int n; double cold_ms, warm_ms, delta, p0; int it_cold, it_warm; };

Row run(int n, int repeats) {
  const double a = std::cbrt(3 * kQ * kR / (2 * kE));
  const double w = 3.0 * a, d = w / n;
  kegel::CellContactModel model(n, n, d, d, kE);
  std::vector<double> h(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5 - 0.5 * n) * d, y = (j + 0.5 - 0.5 * n) * d;
      h[i * n + j] = (x * x + y * y) / (2 * kR);
    }
  std::vector<double> cold, warm;
  Row row{n, 0, 0, 0, 0, 0, 0};
  kegel::CellContactSettings s;
  s.tolerance = 1e-8;
  for (int r = 0; r < repeats; ++r) {
    kegel::CellContactData data(model);
    auto t0 = std::chrono::steady_clock::now();
    kegel::solve_cell_contact(model, data, h.data(), kQ, s);
    auto t1 = std::chrono::steady_clock::now();
    row.it_cold = data.iterations;
    cold.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    // a time step later: the load changed by 1 %
    t0 = std::chrono::steady_clock::now();
    kegel::solve_cell_contact(model, data, h.data(), 1.01 * kQ, s);
    t1 = std::chrono::steady_clock::now();
    row.it_warm = data.iterations;
    warm.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    kegel::solve_cell_contact(model, data, h.data(), kQ, s);
    row.delta = data.approach_m;
    row.p0 = *std::max_element(data.pressure_Pa.begin(), data.pressure_Pa.end());
  }
  std::sort(cold.begin(), cold.end());
  std::sort(warm.begin(), warm.end());
  row.cold_ms = cold[repeats / 2];
  row.warm_ms = warm[repeats / 2];
  return row;
}
}  // namespace

int main() {
  const double a = std::cbrt(3 * kQ * kR / (2 * kE));
  const double delta_h = a * a / kR, p0_h = 3 * kQ / (2 * kPi * a * a);
  const Row finest = run(128, 3);
  std::printf("cell model, sphere R = 10 mm on a flat, Q = 100 N, window 3a; medians of repeated runs\n");
  std::printf("%6s %12s %12s %9s %9s %16s %16s %14s\n", "cells", "cold [ms]", "warm [ms]", "it cold",
              "it warm", "delta vs finest", "delta vs Hertz", "p0 vs Hertz");
  for (int n : {16, 32, 64, 128}) {
    const Row r = n == 128 ? finest : run(n, n <= 32 ? 21 : 7);
    std::printf("%3dx%-3d %11.3f %12.3f %9d %9d %15.3f%% %15.3f%% %13.3f%%\n", n, n, r.cold_ms, r.warm_ms,
                r.it_cold, r.it_warm, 100 * (r.delta / finest.delta - 1), 100 * (r.delta / delta_h - 1),
                100 * (r.p0 / p0_h - 1));
  }
  std::printf("targets at 32x32: warm <= 0.5 ms, cold <= 5 ms\n");
  return 0;
}
