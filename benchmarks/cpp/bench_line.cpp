// Benchmark: one roller/raceway slice contact (32216 roller, crowned, 1000 N/mm, 0.5 mrad tilt),
// displacement-controlled as in the multibody step; median runtime beside the error of the
// contact force against the finest slicing, for both slice models.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "kegel/core/line_contact.hpp"

namespace {
constexpr double kE = 210e9 / 0.91, kL = 22.7e-3, kQ = 1000.0 * 20.7, kTilt = 0.5e-3;

kegel::RollerProfile profile() {
  kegel::RollerProfile::Values v;
  v.roller_diameter_m = 17e-3; v.length_m = kL; v.a_p = 0.0005; v.c_p_m = 20.7e-3; v.d_p_m = 0.0;
  v.k_p_m = 2e-3; v.edge_radius_m = 1e-3;
  return kegel::RollerProfile(v);
}

struct Result { double warm_us, cold_us, force, moment; };

Result run(int n, kegel::SliceMethod method, double delta0, int repeats) {
  const auto p = profile();
  kegel::LineContactModel m(n, kL, std::vector<double>(n, 7.25e-3), kE, method);
  std::vector<double> e(n);
  for (int i = 0; i < n; ++i) e[i] = delta0 - p.drop_m(m.position_m(i)) - kTilt * m.position_m(i);
  std::vector<double> cold, warm;
  Result r{};
  for (int k = 0; k < repeats; ++k) {
    kegel::LineContactData d(m);
    auto t0 = std::chrono::steady_clock::now();
    kegel::solve_line_contact(m, d, e.data());
    auto t1 = std::chrono::steady_clock::now();
    cold.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    for (double& v : e) v += 1e-8;  // next time step: 10 nm more approach
    t0 = std::chrono::steady_clock::now();
    kegel::solve_line_contact(m, d, e.data());
    t1 = std::chrono::steady_clock::now();
    warm.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    for (double& v : e) v -= 1e-8;
    kegel::solve_line_contact(m, d, e.data());
    r.force = d.force_N;
    r.moment = d.moment_Nm;
  }
  std::sort(cold.begin(), cold.end());
  std::sort(warm.begin(), warm.end());
  r.cold_us = cold[repeats / 2];
  r.warm_us = warm[repeats / 2];
  return r;
}
}  // namespace

int main() {
  // the approach that carries kQ at the finest AST slicing
  const auto p = profile();
  const int nf = 200;
  kegel::LineContactModel mf(nf, kL, std::vector<double>(nf, 7.25e-3), kE, kegel::SliceMethod::AlternativeSlicing);
  kegel::LineContactData df(mf);
  std::vector<double> gap(nf);
  for (int i = 0; i < nf; ++i) gap[i] = p.drop_m(mf.position_m(i)) + kTilt * mf.position_m(i);
  double delta0 = 0.0;
  kegel::solve_line_contact_load(mf, df, gap.data(), kQ, delta0);
  const double F_ref = df.force_N, M_ref = df.moment_Nm;
  std::printf("slice contact, 32216 roller, crowned, 1000 N/mm, 0.5 mrad tilt, fixed approach %.3f um\n",
              delta0 * 1e6);
  std::printf("%-20s %6s %10s %10s %15s %15s %15s\n", "method", "slices", "warm [us]", "cold [us]",
              "force vs own", "moment vs own", "force vs AST");
  std::printf("%-20s %6s %10s %10s %15s %15s %15s\n", "", "", "", "", "finest (200)", "finest (200)", "finest");
  for (auto method : {kegel::SliceMethod::Independent, kegel::SliceMethod::AlternativeSlicing}) {
    const Result finest = run(200, method, delta0, 5);
    for (int n : {10, 20, 30, 60, 100, 200}) {
      const Result r = n == 200 ? finest : run(n, method, delta0, n <= 60 ? 101 : 11);
      std::printf("%-20s %6d %10.2f %10.2f %14.2f%% %14.2f%% %14.2f%%\n",
                  method == kegel::SliceMethod::Independent ? "independent" : "alternative (AST)", n, r.warm_us,
                  r.cold_us, 100 * (r.force / finest.force - 1), 100 * (r.moment / finest.moment - 1),
                  100 * (r.force / F_ref - 1));
    }
  }
  (void)M_ref;
  std::printf("target: one pair at 30 slices <= 10 us\n");
  return 0;
}
