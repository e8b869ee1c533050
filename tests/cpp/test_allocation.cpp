// The hot-loop kernels must not allocate: count global operator new calls around them.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "kegel/core/slice.hpp"
#include "test_data.hpp"

namespace {
std::atomic<long> g_news{0};
}
// for the other test files of this binary (test_dynamics.cpp)
long kegel_test_allocation_count() { return g_news.load(); }
void* operator new(std::size_t n) {
  g_news.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

TEST(Allocation, EvaluateSliceDoesNotAllocate) {
  const kegel::Lubricant lub{kegel::test::fva3()};
  const auto state = kegel::make_contact_lubricant_state(lub, 323.15);
  kegel::FrictionParameters::Values v;
  v.gamma_L = 0.06; v.mu_s = 0.1; v.mu_d = 0.1; v.v_s_m_s = 1e-3; v.v_d_m_s = 2e-3; v.a_v = 0.007;
  const kegel::FrictionParameters fp(v);
  const kegel::SurfacePair sp(0.16e-6, 2.32, 0.97, 2.3e11);
  kegel::SliceInput in;
  in.load_N = 80.0; in.width_m = 7e-4; in.reduced_radius_m = 7.5e-3; in.u1_x_m_s = 5.05; in.u2_x_m_s = 5.0;
  kegel::SliceResult out;
  const long before = g_news.load();
  for (int i = 0; i < 1000; ++i) {
    in.load_N = 10.0 + i;
    kegel::evaluate_slice(in, sp, state, fp, out);
  }
  EXPECT_EQ(g_news.load() - before, 0);
  EXPECT_TRUE(out.in_contact);
}
