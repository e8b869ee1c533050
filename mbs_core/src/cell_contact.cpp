#include "kegel/core/cell_contact.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>

#include "kegel/core/checks.hpp"

namespace kegel {
namespace {
constexpr double kPi = 3.14159265358979323846;

// t * [asinh(s2/|t|) - asinh(s1/|t|)], with the limit 0 for t -> 0
inline double term(double t, double s2, double s1) noexcept {
  const double at = std::abs(t);
  if (at < 1e-300) return 0.0;
  return t * (std::asinh(s2 / at) - std::asinh(s1 / at));
}

// FFTW's planner is not thread-safe.
std::mutex& fftw_mutex() {
  static std::mutex m;
  return m;
}
}  // namespace

double love_rectangle_integral(double x, double y, double a, double b) noexcept {
  // Johnson, Contact Mechanics (1985), Eq. 3.25, written with asinh for numerical robustness:
  // ln(s + sqrt(s^2 + t^2)) = ln|t| + asinh(s/|t|), and the ln|t| cancel in each ratio.
  return term(x + a, y + b, y - b) + term(y + b, x + a, x - a) + term(x - a, y - b, y + b) +
         term(y - b, x - a, x + a);
}

struct CellContactData::Fft {
  int nx2 = 0, ny2 = 0, nyc = 0;
  double* real = nullptr;              // (2nx) x (2ny)
  fftw_complex* spec = nullptr;        // (2nx) x (ny + 1)
  fftw_plan forward = nullptr, backward = nullptr;
  ~Fft() {
    std::lock_guard<std::mutex> lock(fftw_mutex());
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
    fftw_free(real);
    fftw_free(spec);
  }
};

namespace {
// Plans + buffers for a (2nx) x (2ny) real <-> complex transform.
std::unique_ptr<CellContactData::Fft> make_fft(int nx, int ny);
}  // namespace

CellContactModel::CellContactModel(int nx, int ny, double dx, double dy, double E)
    : nx_(nx), ny_(ny), dx_(dx), dy_(dy), E_(E) {
  if (nx < 2 || ny < 2 || nx > 4096 || ny > 4096) {
    throw std::invalid_argument("CellContactModel: nx = " + std::to_string(nx) + ", ny = " +
                                std::to_string(ny) + ": expected 2..4096 cells per side");
  }
  detail::require_positive("CellContactModel", "dx_m", dx);
  detail::require_positive("CellContactModel", "dy_m", dy);
  detail::require_positive("CellContactModel", "E_reduced_Pa", E);
  // Padded kernel in wrap-around order (DC-FFT), transformed once.
  auto fft = make_fft(nx, ny);
  const int nx2 = 2 * nx, ny2 = 2 * ny;
  std::fill(fft->real, fft->real + nx2 * ny2, 0.0);
  for (int i = 0; i < nx2; ++i) {
    if (i == nx) continue;
    const int di = i < nx ? i : i - nx2;
    for (int j = 0; j < ny2; ++j) {
      if (j == ny) continue;
      const int dj = j < ny ? j : j - ny2;
      fft->real[i * ny2 + j] = influence(di, dj);
    }
  }
  fftw_execute_dft_r2c(fft->forward, fft->real, fft->spec);
  kernel_.resize(size_t(2 * nx - 1) * (2 * ny - 1));
  for (int di = -(nx - 1); di < nx; ++di)
    for (int dj = -(ny - 1); dj < ny; ++dj)
      kernel_[(di + nx - 1) * (2 * ny - 1) + (dj + ny - 1)] = influence(di, dj);
  const int nc = nx2 * (ny + 1);
  kernel_hat_.resize(nc);
  const double scale = 1.0 / (double(nx2) * double(ny2));  // FFTW transforms are unnormalised
  for (int k = 0; k < nc; ++k) kernel_hat_[k] = {fft->spec[k][0] * scale, fft->spec[k][1] * scale};
}

CellContactModel::~CellContactModel() = default;

double CellContactModel::influence(int di, int dj) const noexcept {
  return 2.0 / (kPi * E_) * love_rectangle_integral(di * dx_, dj * dy_, 0.5 * dx_, 0.5 * dy_);
}

namespace {
std::unique_ptr<CellContactData::Fft> make_fft(int nx, int ny) {
  auto f = std::make_unique<CellContactData::Fft>();
  f->nx2 = 2 * nx;
  f->ny2 = 2 * ny;
  f->nyc = ny + 1;
  std::lock_guard<std::mutex> lock(fftw_mutex());
  f->real = fftw_alloc_real(size_t(f->nx2) * f->ny2);
  f->spec = fftw_alloc_complex(size_t(f->nx2) * f->nyc);
  if (!f->real || !f->spec) throw std::bad_alloc();
  f->forward = fftw_plan_dft_r2c_2d(f->nx2, f->ny2, f->real, f->spec, FFTW_MEASURE);
  f->backward = fftw_plan_dft_c2r_2d(f->nx2, f->ny2, f->spec, f->real, FFTW_MEASURE);
  if (!f->forward || !f->backward) throw std::runtime_error("FFTW could not create a plan");
  return f;
}
}  // namespace

CellContactData::CellContactData(const CellContactModel& model)
    : pressure_Pa(model.cells(), 0.0),
      displacement_m(model.cells(), 0.0),
      model_(&model),
      fft_(make_fft(model.nx(), model.ny())),
      g_(model.cells()),
      t_(model.cells()),
      r_(model.cells()),
      p_old_(model.cells()) {}

CellContactData::~CellContactData() = default;

void CellContactData::convolve(const double* p, double* u) noexcept {
  const int nx = model_->nx(), ny = model_->ny();
  Fft& f = *fft_;
  std::fill(f.real, f.real + f.nx2 * f.ny2, 0.0);
  for (int i = 0; i < nx; ++i) std::memcpy(f.real + i * f.ny2, p + i * ny, sizeof(double) * ny);
  fftw_execute_dft_r2c(f.forward, f.real, f.spec);
  const auto& K = model_->kernel_hat();
  const int nc = f.nx2 * f.nyc;
  for (int k = 0; k < nc; ++k) {
    const double a = f.spec[k][0], b = f.spec[k][1];
    const double c = K[k].real(), d = K[k].imag();
    f.spec[k][0] = a * c - b * d;
    f.spec[k][1] = a * d + b * c;
  }
  fftw_execute_dft_c2r(f.backward, f.spec, f.real);
  for (int i = 0; i < nx; ++i) std::memcpy(u + i * ny, f.real + i * f.ny2, sizeof(double) * ny);
}

int solve_cell_contact(const CellContactModel& m, CellContactData& d, const double* h0,
                       double load, const CellContactSettings& s) noexcept {
  const int n = m.cells();
  if (!(load > 0.0) || !std::isfinite(load)) return -1;
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(h0[i])) return -1;
  const double A = m.dx_m() * m.dy_m();
  double* p = d.pressure_Pa.data();
  double* u = d.displacement_m.data();
  double* g = d.g_.data();
  double* t = d.t_.data();
  double* r = d.r_.data();
  double* p_old = d.p_old_.data();

  // Start: the previous pressure scaled to the new load, or a uniform pressure over the cells
  // within the closest 10 % of the gap range (a cold start).
  double sum = 0.0;
  if (s.warm_start && d.has_solution) {
    for (int i = 0; i < n; ++i) sum += p[i];
  }
  if (sum > 0.0) {
    const double k = load / (sum * A);
    for (int i = 0; i < n; ++i) p[i] *= k;
  } else {
    const double hmin = *std::min_element(h0, h0 + n), hmax = *std::max_element(h0, h0 + n);
    const double cut = hmin + 0.1 * (hmax - hmin);
    int count = 0;
    for (int i = 0; i < n; ++i) count += h0[i] <= cut;
    for (int i = 0; i < n; ++i) p[i] = h0[i] <= cut ? load / (count * A) : 0.0;
  }
  std::fill(t, t + n, 0.0);

  // The displacement u = K * p is kept up to date incrementally: the CG step changes p by
  // -tau t (so u by -tau K*t, which the step computes anyway), and only the few cells that the
  // projection p >= 0 or the overlap rule change need a direct correction. A full FFT
  // convolution is taken when many cells change, and at the end.
  const int nx = m.nx(), ny = m.ny(), kw = 2 * ny - 1;
  const double* K = m.kernel().data();
  auto add_cell = [&](int k, double c) {  // u += c * K(. - k)
    const int ki = k / ny, kj = k % ny;
    for (int i = 0; i < nx; ++i) {
      const double* row = K + (i - ki + nx - 1) * kw + (ny - 1 - kj);
      double* ui = u + i * ny;
      for (int j = 0; j < ny; ++j) ui[j] += c * row[j];
    }
  };
  const int direct_limit = std::max(1, n / 64);

  d.convolve(p, u);
  double G_old = 1.0, g_mean = 0.0, err = 0.0;
  bool delta = false;
  int it = 0, status = 1;
  for (; it < s.max_iterations; ++it) {
    // gap and its mean over the contact set
    int nc = 0;
    g_mean = 0.0;
    for (int i = 0; i < n; ++i) {
      g[i] = h0[i] + u[i];
      if (p[i] > 0.0) {
        g_mean += g[i];
        ++nc;
      }
    }
    if (nc == 0) return -1;
    g_mean /= nc;
    double G = 0.0;
    for (int i = 0; i < n; ++i) {
      g[i] -= g_mean;
      if (p[i] > 0.0) G += g[i] * g[i];
    }
    // conjugate direction
    const double beta = delta ? G / G_old : 0.0;
    for (int i = 0; i < n; ++i) t[i] = p[i] > 0.0 ? g[i] + beta * t[i] : 0.0;
    G_old = G;
    d.convolve(t, r);  // raw K * t, kept for the displacement update
    double r_mean = 0.0;
    for (int i = 0; i < n; ++i)
      if (p[i] > 0.0) r_mean += r[i];
    r_mean /= nc;
    double num = 0.0, den = 0.0;
    for (int i = 0; i < n; ++i) {
      if (p[i] > 0.0) {
        num += g[i] * t[i];
        den += (r[i] - r_mean) * t[i];
      }
    }
    if (!(den > 0.0)) {  // converged to round-off (or degenerate direction)
      status = 0;
      break;
    }
    const double tau = num / den;
    std::memcpy(p_old, p, sizeof(double) * n);
    for (int i = 0; i < n; ++i) u[i] -= tau * r[i];
    // projection and overlap: collect the cells whose change is not -tau t
    int changed = 0;
    bool overlap = false;
    for (int i = 0; i < n; ++i) {
      if (p[i] > 0.0) {
        const double v = p[i] - tau * t[i];
        if (v < 0.0) {
          p[i] = 0.0;
          r[i] = -v;  // correction (r is free now): actual minus linear change
          ++changed;
        } else {
          p[i] = v;
          r[i] = 0.0;
        }
      } else if (g[i] < 0.0) {  // cells outside the contact with a negative gap enter it
        p[i] = -tau * g[i];
        r[i] = p[i];
        overlap = true;
        ++changed;
      } else {
        r[i] = 0.0;
      }
    }
    delta = !overlap;
    if (changed > direct_limit) {
      // many changes: recompute below after the load balance
    } else if (changed > 0) {
      for (int i = 0; i < n; ++i)
        if (r[i] != 0.0) add_cell(i, r[i]);
    }
    // load balance
    double P = 0.0;
    for (int i = 0; i < n; ++i) P += p[i];
    P *= A;
    if (!(P > 0.0) || !std::isfinite(P)) return -1;
    const double k = load / P;
    err = 0.0;
    for (int i = 0; i < n; ++i) {
      p[i] *= k;
      err += std::abs(p[i] - p_old[i]);
    }
    if (changed > direct_limit) {
      d.convolve(p, u);
    } else {
      for (int i = 0; i < n; ++i) u[i] *= k;
    }
    err *= A / load;
    if (err < s.tolerance) {
      status = 0;
      ++it;
      break;
    }
  }
  // final displacement and approach with the final pressure
  d.convolve(p, u);
  double alpha = 0.0;
  int nc = 0;
  for (int i = 0; i < n; ++i) {
    if (p[i] > 0.0) {
      alpha += h0[i] + u[i];
      ++nc;
    }
  }
  d.approach_m = nc ? alpha / nc : 0.0;
  d.load_N = load;
  d.iterations = it;
  d.residual = err;
  d.has_solution = true;
  return status;
}

}  // namespace kegel
