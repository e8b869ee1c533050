// Python entry points of the quasi-static solution (kegel._core.quasi_static).
#include <nanobind/eigen/dense.h>
#include <nanobind/stl/vector.h>
#include <nanobind/stl/string.h>

#include <stdexcept>

#include "bindings.hpp"
#include "kegel/core/quasi_static.hpp"

namespace nb = nanobind;
using namespace nb::literals;

namespace kegel::python {

void bind_quasi_static(nb::module_& parent) {
  nb::module_ m = parent.def_submodule("quasi_static", "Quasi-static load distribution (SI units).");
  using V = BearingModelValues;
  nb::class_<V>(m, "BearingModelValues")
      .def(nb::init<>())
      .def_rw("roller_count", &V::roller_count)
      .def_rw("pitch_radius_m", &V::pitch_radius_m)
      .def_rw("roller_mid_z_m", &V::roller_mid_z_m)
      .def_rw("roller_axis_angle_rad", &V::roller_axis_angle_rad)
      .def_rw("apex_z_m", &V::apex_z_m)
      .def_rw("cup_angle_rad", &V::cup_angle_rad)
      .def_rw("cone_angle_rad", &V::cone_angle_rad)
      .def_rw("roller_mean_radius_m", &V::roller_mean_radius_m)
      .def_rw("roller_half_angle_rad", &V::roller_half_angle_rad)
      .def_rw("roller_length_m", &V::roller_length_m)
      .def_rw("roller_mass_kg", &V::roller_mass_kg)
      .def_rw("cage_pocket_clearance_m", &V::cage_pocket_clearance_m)
      .def_rw("E_reduced_Pa", &V::E_reduced_Pa)
      .def_rw("rib_apex_z_m", &V::rib_apex_z_m)
      .def_rw("rib_half_angle_rad", &V::rib_half_angle_rad)
      .def_rw("rib_outer_radius_m", &V::rib_outer_radius_m)
      .def_rw("end_sphere_radius_m", &V::end_sphere_radius_m)
      .def_rw("end_cap_radius_m", &V::end_cap_radius_m)
      .def_rw("end_sphere_offset_m", &V::end_sphere_offset_m)
      .def_rw("slices", &V::slices)
      .def_rw("method", &V::method)
      .def(
          "set_profile",
          [](V& v, double D, double L, double a_p, double c_p, double d_p, double k_p, double r_e) {
            v.profile = {D, L, a_p, c_p, d_p, k_p, r_e};
          },
          "roller_diameter_m"_a, "length_m"_a, "a_p"_a, "c_p_m"_a, "d_p_m"_a, "k_p_m"_a, "edge_radius_m"_a);
  nb::class_<BearingModel>(m, "BearingModel")
      .def(nb::init<const V&>(), "values"_a)
      .def_prop_ro("rib_Rx_m", &BearingModel::rib_Rx_m)
      .def_prop_ro("rib_Ry_m", &BearingModel::rib_Ry_m);
  nb::class_<BearingLoads>(m, "BearingLoads")
      .def(nb::init<>())
      .def_rw("axial_N", &BearingLoads::axial_N)
      .def_rw("radial_N", &BearingLoads::radial_N)
      .def_rw("tilt_moment_Nm", &BearingLoads::tilt_moment_Nm)
      .def_rw("misalignment_x_rad", &BearingLoads::misalignment_x_rad)
      .def_rw("misalignment_y_rad", &BearingLoads::misalignment_y_rad)
      .def_rw("tilt_free", &BearingLoads::tilt_free)
      .def_rw("axial_offset_controlled", &BearingLoads::axial_offset_controlled)
      .def_rw("axial_offset_m", &BearingLoads::axial_offset_m)
      .def_rw("cage_speed_rad_s", &BearingLoads::cage_speed_rad_s);
  nb::class_<RollerState>(m, "RollerState")
      .def_ro("u_m", &RollerState::u_m)
      .def_ro("w_m", &RollerState::w_m)
      .def_ro("tilt_rad", &RollerState::tilt_rad)
      .def_ro("outer_N", &RollerState::outer_N)
      .def_ro("inner_N", &RollerState::inner_N)
      .def_ro("rib_N", &RollerState::rib_N)
      .def_ro("residual", &RollerState::residual);
  nb::class_<BearingData>(m, "BearingData")
      .def(nb::init<const BearingModel&>(), "model"_a)
      .def_prop_ro("ring", [](const BearingData& d) { return Eigen::VectorXd(d.ring); })
      .def_ro("rollers", &BearingData::rollers)
      .def_ro("residual", &BearingData::residual)
      .def_prop_ro("reaction_moment_Nm", [](const BearingData& d) { return Eigen::Vector2d(d.reaction_moment_Nm); })
      .def_ro("axial_force_N", &BearingData::axial_force_N)
      .def_ro("iterations", &BearingData::iterations);
  m.def(
      "loaded_lengths_m",
      [](const BearingModel& model, const BearingData& data) {
        const std::size_t Z = data.rollers.size();
        if (!data.has_solution || data.inner_lines.size() != Z || data.outer_lines.size() != Z)
          throw std::invalid_argument("BearingData: no solved load distribution");
        Eigen::MatrixXd out(static_cast<Eigen::Index>(Z), 2);
        const double wi = model.inner_line().width_m(), wo = model.outer_line().width_m();
        for (std::size_t k = 0; k < Z; ++k) {
          const std::size_t j = data.symmetric ? 0 : k;  // an axisymmetric case solves roller 0 only
          double li = 0.0, lo = 0.0;
          for (double q : data.inner_lines[j].line_load_N_m) if (q > 0.0) li += wi;
          for (double q : data.outer_lines[j].line_load_N_m) if (q > 0.0) lo += wo;
          out(static_cast<Eigen::Index>(k), 0) = li;
          out(static_cast<Eigen::Index>(k), 1) = lo;
        }
        return out;
      },
      "model"_a, "data"_a,
      "Loaded length [m] of each roller's line contacts at a solved load distribution: the widths "
      "of the slices that carry load, one row per roller, columns (inner, outer).");
  m.def(
      "solve_load_distribution",
      [](const BearingModel& model, BearingData& data, const BearingLoads& loads) {
        const int status = solve_load_distribution(model, data, loads);
        if (status < 0) throw std::invalid_argument("BearingLoads: expected finite loads >= 0, not all zero");
        return status;
      },
      "model"_a, "data"_a, "loads"_a, "Solve the load distribution; 0 = converged.");
  nb::enum_<CageModel>(m, "CageModel")
      .value("off", CageModel::Off)
      .value("pocket", CageModel::Pocket)
      .value("free_rollers", CageModel::FreeRollers)
      .value("walls", CageModel::Walls);
  nb::enum_<RibPressure>(m, "RibPressure")
      .value("hertz", RibPressure::Hertz)
      .value("solved", RibPressure::Solved);
  m.def(
      "evaluate_bearing_friction",
      [](const BearingModel& model, BearingData& data, const BearingLoads& loads, double inner_speed,
         const ContactLubricantState& lub, const FrictionParameters& fp, const SurfacePair& race,
         const SurfacePair& rib, int rib_cells, CageModel cage, const ContactLubricantState* outer_lub,
         const ContactLubricantState* inner_lub, RibPressure rib_pressure) {
        BearingFriction f;
        const int status = evaluate_bearing_friction(model, data, loads, inner_speed, outer_lub ? *outer_lub : lub,
                                                     inner_lub ? *inner_lub : lub, fp, race, rib, f, rib_cells, cage,
                                                     rib_pressure);
        if (status < 0) throw std::invalid_argument("evaluate_bearing_friction: solve the load distribution first, "
                                                    "with a finite non-zero inner-ring speed and 0 <= rib_cells <= 256 (cage = walls: a model with cage_pocket_clearance_m > 0)");
        nb::dict d;
        d["status"] = status;
        d["inner_speed_rad_s"] = f.inner_speed_rad_s;
        d["cage_speed_rad_s"] = f.cage_speed_rad_s;
        d["cage_speed_pure_rolling_rad_s"] = f.cage_speed_pure_rolling_rad_s;
        d["roller_spin_rad_s"] = f.roller_spin_rad_s;
        d["roller_orbit_rad_s"] = f.roller_orbit_rad_s;
        d["roller_drift_m"] = f.roller_drift_m;
        d["locked_rollers"] = f.locked_rollers;
        d["pocket_moment_free_Nm"] = f.pocket_moment_free_Nm;
        d["roller_spin_pure_rolling_rad_s"] = f.roller_spin_pure_rolling_rad_s;
        d["drive_torque_Nm"] = f.drive_torque_Nm;
        d["outer_ring_torque_Nm"] = f.outer_ring_torque_Nm;
        d["power_input_W"] = f.power_input_W;
        d["power_dissipated_W"] = f.power_dissipated_W;
        d["cage_power_W"] = f.cage_power_W;
        d["cage_residual_Nm"] = f.cage_residual_Nm;
        d["pocket_fraction"] = f.pocket_fraction;
        d["roller_wall_share"] = f.roller_wall_share;
        d["rib_edge_rollers"] = f.rib_edge_rollers;
        put_friction_by_contact(d, f.power_W, f.Lambda_min, f.phi_max);
        return d;
      },
      "model"_a, "data"_a, "loads"_a, "inner_speed_rad_s"_a, "lubricant_state"_a, "friction"_a, "raceway"_a,
      "rib"_a, "rib_cells"_a = 0, "cage"_a = CageModel::FreeRollers, "outer_lubricant_state"_a.none() = nb::none(),
      "inner_lubricant_state"_a.none() = nb::none(), "rib_pressure"_a = RibPressure::Hertz,
      "Friction of the whole bearing at the solved load distribution (rib_cells > 0: rib cell model, its "
      "pressure field as rib_pressure says: Hertz's ellipse unless an edge cuts it, or solved for every roller). "
      "outer_lubricant_state / inner_lubricant_state (default: lubricant_state): the lubricant state of the "
      "outer ring's contacts and of the inner ring's (its raceway and the rib), for a contact temperature per ring.");
}

}  // namespace kegel::python
