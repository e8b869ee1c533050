// Benchmark: per-slice friction evaluation (all mechanisms), median over repeated runs, and a
// count of heap allocations inside the timed loop (must be 0).
//
// Run: make bench   (or build/bench/bench_slice after `cmake --build build/bench`)
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <vector>

#include "kegel/core/slice.hpp"

static std::atomic<long> g_allocations{0};
void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

int main() {
  kegel::LubricantParameters p;
  p.vogel_K_Pas = 0.062e-3; p.vogel_B_K = 1021.7; p.vogel_C_degC = 101.5517;
  p.dicke_a1_bar = 327.7918; p.dicke_a2_bar_per_K = 2.9862; p.dicke_b1 = 4.419e-3;
  p.dicke_b2_per_K = 3.0115e-4; p.density_ref_kg_m3 = 887.6; p.density_ref_temperature_K = 288.15;
  p.density_slope_kg_m3_K = -0.6; p.thermal_conductivity_W_mK = 0.134;
  const kegel::Lubricant lub(p);
  const auto state = kegel::make_contact_lubricant_state(lub, 323.15);
  kegel::FrictionParameters::Values v;
  v.gamma_L = 0.06; v.mu_s = 0.1; v.mu_d = 0.1; v.v_s_m_s = 1e-3; v.v_d_m_s = 2e-3;
  v.c_r = 5e-6; v.e_r = 1.0; v.a_v = 0.007;
  const kegel::FrictionParameters fp(v);
  const kegel::SurfacePair sp(0.16e-6, 2.32, 0.97, 210e9 / 0.91);

  // 30 slices of one 32216 inner contact (~2.5 kN), with a crowned load profile and 1 % slip
  constexpr int kSlices = 30;
  std::vector<kegel::SliceInput> in(kSlices);
  for (int i = 0; i < kSlices; ++i) {
    const double x = (i + 0.5) / kSlices - 0.5;
    in[i].load_N = 2500.0 / kSlices * 1.5 * (1.0 - 4.0 * x * x * 0.5);
    in[i].width_m = 20.7e-3 / kSlices;
    in[i].reduced_radius_m = 7.3e-3 + 0.4e-3 * x;
    in[i].u2_x_m_s = 4.8 + 0.4 * x;
    in[i].u1_x_m_s = in[i].u2_x_m_s * 1.01;
    in[i].u1_y_m_s = 1e-3 * x;
  }
  std::vector<kegel::SliceResult> out(kSlices);

  constexpr int kRepeats = 15, kPasses = 4000;
  std::vector<double> ns_per_slice;
  double sink = 0.0;
  long allocations = 0;
  for (int r = 0; r < kRepeats; ++r) {
    const long a0 = g_allocations.load();
    const auto t0 = std::chrono::steady_clock::now();
    for (int pass = 0; pass < kPasses; ++pass) {
      for (int i = 0; i < kSlices; ++i) kegel::evaluate_slice(in[i], sp, state, fp, out[i]);
      sink += out[pass % kSlices].F_ehl_sliding_N[0];
    }
    const auto t1 = std::chrono::steady_clock::now();
    allocations += g_allocations.load() - a0;
    ns_per_slice.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / (kPasses * kSlices));
  }
  std::sort(ns_per_slice.begin(), ns_per_slice.end());
  std::printf("evaluate_slice (all mechanisms, 30-slice contact, %d x %d passes)\n", kRepeats, kPasses);
  std::printf("  median %.1f ns/slice   min %.1f   max %.1f   target <= 1000 ns\n",
              ns_per_slice[kRepeats / 2], ns_per_slice.front(), ns_per_slice.back());
  std::printf("  heap allocations in the timed loop: %ld (must be 0)\n", allocations);
  std::printf("  (checksum %.6g)\n", sink);
  return allocations == 0 ? 0 : 1;
}
