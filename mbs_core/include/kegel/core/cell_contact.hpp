// Cell model of a non-Hertzian contact (roller large end / rib; seed paper Section 2.1.1):
// the contact window is divided into rectangular cells of uniform pressure, the surface
// displacement follows from Boussinesq's half-space solution integrated over each cell (Love's
// rectangle influence coefficients), the convolution is evaluated with FFTs on a zero-padded
// grid (DC-FFT: Liu, Wang and Liu, Wear 243 (2000) 101-111), and the contact problem is solved
// with the conjugate-gradient method of Polonsky and Keer (Wear 231 (1999) 206-219), in load
// control, warm-started from the previous pressure field.
//
// Model / Data split: CellContactModel holds the grid and the influence coefficients in Fourier
// space (built once); CellContactData holds the pressure field (the warm start), the FFT plans
// and every work array. solve_cell_contact() allocates nothing.
#pragma once

#include <complex>
#include <memory>
#include <vector>

namespace kegel {

/// Love's influence function: integral of 1/r over a rectangle of half-sizes a, b centred at
/// the origin, seen from the surface point (x, y). The combined surface displacement of two
/// elastic half-spaces under a uniform pressure p on that rectangle is (2 / (pi E')) p f.
double love_rectangle_integral(double x, double y, double a, double b) noexcept;

/// Solver settings.
struct CellContactSettings {
  double tolerance = 1e-9;   ///< relative change of the pressure field (L1, load-normalised)
  int max_iterations = 2000;
  bool warm_start = true;    ///< start from the pressure of the previous solve when there is one
};

/// Grid and influence coefficients (the Model).
class CellContactModel {
 public:
  /// @param nx, ny        cells in x and y (>= 2 each)
  /// @param dx_m, dy_m    cell sizes
  /// @param E_reduced_Pa  E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)
  /// Throws std::invalid_argument on invalid values.
  CellContactModel(int nx, int ny, double dx_m, double dy_m, double E_reduced_Pa);
  ~CellContactModel();
  CellContactModel(const CellContactModel&) = delete;
  CellContactModel& operator=(const CellContactModel&) = delete;

  int nx() const noexcept { return nx_; }
  int ny() const noexcept { return ny_; }
  double dx_m() const noexcept { return dx_; }
  double dy_m() const noexcept { return dy_; }
  double E_reduced_Pa() const noexcept { return E_; }
  int cells() const noexcept { return nx_ * ny_; }

  /// Influence coefficient: displacement of cell (i, j) per unit pressure on cell (0, 0) [m/Pa].
  double influence(int di, int dj) const noexcept;
  /// FFT of the zero-padded kernel, (2 nx) x (ny + 1) complex values (r2c layout).
  const std::vector<std::complex<double>>& kernel_hat() const noexcept { return kernel_hat_; }
  /// Influence coefficients in real space, (2 nx - 1) x (2 ny - 1), index
  /// (di + nx - 1) * (2 ny - 1) + (dj + ny - 1).
  const std::vector<double>& kernel() const noexcept { return kernel_; }

 private:
  int nx_, ny_;
  double dx_, dy_, E_;
  std::vector<double> kernel_;
  std::vector<std::complex<double>> kernel_hat_;  // FFT of the padded kernel, (2nx) x (ny + 1)
};

/// Workspace and state (the Data).
class CellContactData {
 public:
  explicit CellContactData(const CellContactModel& model);
  ~CellContactData();
  CellContactData(const CellContactData&) = delete;
  CellContactData& operator=(const CellContactData&) = delete;

  // Results of the last solve
  std::vector<double> pressure_Pa;       ///< nx * ny, row-major (index i * ny + j)
  std::vector<double> displacement_m;    ///< combined elastic displacement u
  double approach_m = 0.0;               ///< rigid-body approach alpha (h0 + u = alpha in contact)
  double load_N = 0.0;
  int iterations = 0;
  double residual = 0.0;
  bool has_solution = false;

  /// Convolution u = K * p on the model's grid (used by the solver; public for tests).
  void convolve(const double* p, double* u) noexcept;

  struct Fft;  ///< FFTW plans and aligned buffers (opaque)

 private:
  friend int solve_cell_contact(const CellContactModel&, CellContactData&, const double*, double,
                                const CellContactSettings&) noexcept;
  const CellContactModel* model_;
  std::unique_ptr<Fft> fft_;
  std::vector<double> g_, t_, r_, p_old_;
};

/// Solve the contact problem in load control: find p >= 0 with sum(p) dx dy = load and
/// h0 + u - alpha = 0 where p > 0, >= 0 elsewhere. h0 is the undeformed gap (row-major,
/// nx * ny, metres; its minimum need not be zero).
///
/// @return 0 on convergence, 1 if max_iterations was reached (the last iterate is kept),
///         -1 for invalid input (load <= 0, non-finite gap) - nothing is thrown.
int solve_cell_contact(const CellContactModel& model, CellContactData& data, const double* h0_m,
                       double load_N, const CellContactSettings& settings = {}) noexcept;

}  // namespace kegel
