// Python entry points of the contact models (kegel._core.contact). Arguments are checked here
// (ValueError) before the noexcept kernels run; arrays travel as lists of floats (row-major).
#include <nanobind/eigen/dense.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "kegel/core/cell_contact.hpp"
#include "kegel/core/contact_geometry.hpp"
#include "kegel/core/hertz.hpp"
#include "kegel/core/line_contact.hpp"

namespace nb = nanobind;
using namespace nb::literals;

namespace kegel::python {
namespace {

void check_finite(const char* what, const std::vector<double>& v) {
  for (size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw std::invalid_argument(std::string(what) + "[" + std::to_string(i) + "] = " + std::to_string(v[i]) +
                                  ": expected a finite value");
}

nb::dict slice_geometry_dict(const std::vector<SliceGeometry>& g) {
  std::vector<double> e, R;
  std::vector<std::vector<double>> p, n, tr, tl;
  for (const auto& s : g) {
    e.push_back(s.interference_m);
    R.push_back(s.reduced_radius_m);
    p.push_back({s.p_RC.x(), s.p_RC.y(), s.p_RC.z()});
    n.push_back({s.n_R.x(), s.n_R.y(), s.n_R.z()});
    tr.push_back({s.t_roll_R.x(), s.t_roll_R.y(), s.t_roll_R.z()});
    tl.push_back({s.t_line_R.x(), s.t_line_R.y(), s.t_line_R.z()});
  }
  nb::dict d;
  d["interference_m"] = e;
  d["reduced_radius_m"] = R;
  d["p_RC"] = p;
  d["n_R"] = n;
  d["t_roll_R"] = tr;
  d["t_line_R"] = tl;
  return d;
}

nb::dict ellipse_dict(const HertzEllipse& h) {
  nb::dict d;
  d["load_N"] = h.load_N;
  d["approach_m"] = h.approach_m;
  d["semi_major_m"] = h.semi_major_m;
  d["semi_minor_m"] = h.semi_minor_m;
  d["max_pressure_Pa"] = h.max_pressure_Pa;
  d["ellipticity"] = h.ellipticity;
  return d;
}

}  // namespace

void bind_contact(nb::module_& parent) {
  nb::module_ m = parent.def_submodule("contact", "Contact models of the roller (SI units).");

  using PV = RollerProfile::Values;
  nb::class_<RollerProfile>(m, "RollerProfile", "Logarithmic roller crowning plus edge radius.")
      .def(
          "__init__",
          [](RollerProfile* self, double D, double L, double a_p, double c_p, double d_p, double k_p, double r_e) {
            PV v;
            v.roller_diameter_m = D;
            v.length_m = L;
            v.a_p = a_p;
            v.c_p_m = c_p;
            v.d_p_m = d_p;
            v.k_p_m = k_p;
            v.edge_radius_m = r_e;
            new (self) RollerProfile(v);
          },
          "roller_diameter_m"_a, "length_m"_a, "a_p"_a, "c_p_m"_a, "d_p_m"_a, "k_p_m"_a, "edge_radius_m"_a)
      .def("drop_m", &RollerProfile::drop_m, "x_m"_a, "Profile drop at x from the roller middle [m].");

  nb::enum_<SliceMethod>(m, "SliceMethod")
      .value("independent", SliceMethod::Independent)
      .value("alternative_slicing", SliceMethod::AlternativeSlicing);

  m.def("strip_influence_H", &strip_influence_H, "a"_a);

  nb::enum_<ApproachReference>(m, "ApproachReference")
      .value("palmgren", ApproachReference::Palmgren)
      .value("half_space", ApproachReference::HalfSpace);
  m.attr("REFERENCE_LINE_LOAD_N_M") = kReferenceLineLoad_N_m;
  m.def("depth_displacement", &depth_displacement, "x1_m"_a, "x2_m"_a, "depth_m"_a, "E_reduced_Pa"_a,
        "poisson"_a = kReferencePoisson,
        "Boussinesq displacement at a depth below a slice from a unit line load on [x1, x2] (both bodies).");

  nb::class_<LineContactModel>(m, "LineContactModel", "Slices of a roller/raceway line contact.")
      .def(nb::init<int, double, const std::vector<double>&, double, SliceMethod, ApproachReference>(),
           "slices"_a, "length_m"_a, "reduced_radius_m"_a, "E_reduced_Pa"_a, "method"_a,
           "reference"_a = ApproachReference::Palmgren)
      .def_prop_ro("reference_depth_m", &LineContactModel::reference_depth_m)
      .def("set_reference_depth", &LineContactModel::set_reference_depth, "depth_m"_a)
      .def_prop_ro("slices", &LineContactModel::slices)
      .def_prop_ro("width_m", &LineContactModel::width_m)
      .def_prop_ro("length_m", &LineContactModel::length_m)
      .def_prop_ro("positions_m", [](const LineContactModel& lm) {
        std::vector<double> x(lm.slices());
        for (int i = 0; i < lm.slices(); ++i) x[i] = lm.position_m(i);
        return x;
      });
  nb::class_<LineContactData>(m, "LineContactData", "State of a line contact (warm start).")
      .def(nb::init<const LineContactModel&>(), "model"_a)
      .def_ro("line_load_N_m", &LineContactData::line_load_N_m)
      .def_ro("half_width_m", &LineContactData::half_width_m)
      .def_ro("max_pressure_Pa", &LineContactData::max_pressure_Pa)
      .def_ro("force_N", &LineContactData::force_N)
      .def_ro("moment_Nm", &LineContactData::moment_Nm)
      .def_ro("iterations", &LineContactData::iterations);
  m.def(
      "solve_line_contact",
      [](const LineContactModel& lm, LineContactData& d, const std::vector<double>& e) {
        check_size("interference_m", e.size(), lm.slices());
        check_finite("interference_m", e);
        return solve_line_contact(lm, d, e.data());
      },
      "model"_a, "data"_a, "interference_m"_a, "Slice loads for given interferences; 0 = converged.");
  m.def(
      "solve_line_contact_load",
      [](const LineContactModel& lm, LineContactData& d, const std::vector<double>& gap, double force) {
        check_size("gap_m", gap.size(), lm.slices());
        check_finite("gap_m", gap);
        if (!(force > 0.0) || !std::isfinite(force))
          throw std::invalid_argument("force_N = " + std::to_string(force) + ": expected a finite value > 0");
        double approach = 0.0;
        const int status = solve_line_contact_load(lm, d, gap.data(), force, approach);
        if (status != 0) throw std::runtime_error("line contact: the load iteration did not converge");
        return approach;
      },
      "model"_a, "data"_a, "gap_m"_a, "force_N"_a, "Approach [m] that carries the force.");

  nb::class_<CellContactModel>(m, "CellContactModel", "Cell grid and influence coefficients.")
      .def(nb::init<int, int, double, double, double>(), "nx"_a, "ny"_a, "dx_m"_a, "dy_m"_a, "E_reduced_Pa"_a)
      .def_prop_ro("nx", &CellContactModel::nx)
      .def_prop_ro("ny", &CellContactModel::ny);
  nb::class_<CellContactData>(m, "CellContactData", "Pressure field (warm start) and workspace.")
      .def(nb::init<const CellContactModel&>(), "model"_a, nb::keep_alive<1, 2>())
      .def_ro("pressure_Pa", &CellContactData::pressure_Pa)
      .def_ro("displacement_m", &CellContactData::displacement_m)
      .def_ro("approach_m", &CellContactData::approach_m)
      .def_ro("iterations", &CellContactData::iterations)
      .def_ro("residual", &CellContactData::residual);
  m.def(
      "solve_cell_contact",
      [](const CellContactModel& cm, CellContactData& d, const std::vector<double>& h0, double load,
         double tolerance, int max_iterations, bool warm_start) {
        check_size("h0_m", h0.size(), size_t(cm.cells()));
        check_finite("h0_m", h0);
        if (!(load > 0.0) || !std::isfinite(load))
          throw std::invalid_argument("load_N = " + std::to_string(load) + ": expected a finite value > 0");
        CellContactSettings s;
        s.tolerance = tolerance;
        s.max_iterations = max_iterations;
        s.warm_start = warm_start;
        return solve_cell_contact(cm, d, h0.data(), load, s);
      },
      "model"_a, "data"_a, "h0_m"_a, "load_N"_a, "tolerance"_a = 1e-9, "max_iterations"_a = 2000,
      "warm_start"_a = true, "Solve the cell contact in load control; 0 = converged, 1 = iteration limit.");

  m.def(
      "hertz_point_contact_load",
      [](double Rx, double Ry, double E, double Q) {
        if (!(Rx > 0 && Ry > 0 && E > 0 && Q > 0)) throw std::invalid_argument("Rx, Ry, E', Q: expected values > 0");
        return ellipse_dict(hertz_point_contact_load(Rx, Ry, E, Q));
      },
      "Rx_m"_a, "Ry_m"_a, "E_reduced_Pa"_a, "load_N"_a);
  m.def(
      "hertz_point_contact_approach",
      [](double Rx, double Ry, double E, double delta) {
        if (!(Rx > 0 && Ry > 0 && E > 0)) throw std::invalid_argument("Rx, Ry, E': expected values > 0");
        return ellipse_dict(hertz_point_contact_approach(Rx, Ry, E, delta));
      },
      "Rx_m"_a, "Ry_m"_a, "E_reduced_Pa"_a, "approach_m"_a);

  nb::enum_<RacewaySide>(m, "RacewaySide")
      .value("inner", RacewaySide::Inner)
      .value("outer", RacewaySide::Outer);
  m.def(
      "raceway_slice_geometry",
      [](double mean_radius, double half_angle, double length, const RollerProfile& prof,
         const Eigen::Vector3d& p_RM, const Eigen::Vector3d& a_R, double apex_z, double cone_angle,
         RacewaySide side, const std::vector<double>& xi) {
        check_finite("xi_m", xi);
        if (!(a_R.norm() > 0.0)) throw std::invalid_argument("a_R: expected a non-zero axis");
        std::vector<SliceGeometry> out(xi.size());
        raceway_slice_geometry({mean_radius, half_angle, length}, prof, p_RM, a_R, {apex_z, cone_angle}, side,
                               xi.data(), int(xi.size()), out.data());
        return slice_geometry_dict(out);
      },
      "mean_radius_m"_a, "half_angle_rad"_a, "length_m"_a, "profile"_a, "p_RM"_a, "a_R"_a, "apex_z_m"_a,
      "cone_half_angle_rad"_a, "side"_a, "xi_m"_a, "Slice contact geometry of a roller against a raceway cone.");
  m.def(
      "rib_gap",
      [](const Eigen::Vector3d& p_RE, const Eigen::Vector3d& a_R, double R_e, double cap_radius, double apex_z,
         double cone_angle, double rib_outer_radius, int nx, int ny, double dx, double dy) {
        if (nx < 2 || ny < 2 || !(dx > 0) || !(dy > 0)) throw std::invalid_argument("grid: expected nx, ny >= 2 and dx, dy > 0");
        RollerEnd end{p_RE, a_R, R_e, cap_radius};
        RibFace rib{{apex_z, cone_angle}, rib_outer_radius};
        std::vector<double> h(size_t(nx) * ny);
        Eigen::Vector3d p, n;
        const double g = rib_gap(end, rib, nx, ny, dx, dy, h.data(), p, n);
        return std::make_tuple(g, h, p, n);
      },
      "p_RE"_a, "a_R"_a, "sphere_radius_m"_a, "cap_radius_m"_a, "apex_z_m"_a, "cone_half_angle_rad"_a,
      "rib_outer_radius_m"_a, "nx"_a, "ny"_a, "dx_m"_a, "dy_m"_a,
      "Gap between roller end and rib on a cell grid: (min gap, h0, p_RC, n_R).");
}

}  // namespace kegel::python
