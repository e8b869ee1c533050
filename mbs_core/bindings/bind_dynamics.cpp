// Python entry points of the dynamic simulation (kegel._core.dynamics).
#include <nanobind/eigen/dense.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <stdexcept>

#include "bindings.hpp"
#include "kegel/core/dynamics.hpp"

namespace nb = nanobind;
using namespace nb::literals;

namespace kegel::python {
namespace {

// A force element written in Python: callable(body, p, axis, v, w, time_s, inner_speed, cage_speed)
// -> (force_N[3], moment_Nm[3]). The right-hand side runs while Python holds the GIL (the
// integrator is called from Python), so the callable is called directly; an exception is kept
// and stops the run with its message.
class PyForceElement final : public ForceElement {
 public:
  explicit PyForceElement(nb::callable f) : f_(std::move(f)) {}
  int wrench(int body, const BodyKinematics& k, const ForceContext& ctx, Wrench& out) const noexcept override {
    try {
      nb::object r = f_(body, Eigen::Vector3d(k.p_RC), Eigen::Vector3d(k.axis_R), Eigen::Vector3d(k.v_RC),
                        Eigen::Vector3d(k.w_R), ctx.time_s, ctx.inner_speed_rad_s, ctx.cage_speed_rad_s);
      nb::tuple t = nb::cast<nb::tuple>(r);
      if (t.size() != 2) throw std::invalid_argument("expected a tuple (force_N, moment_Nm)");
      out.force_N = nb::cast<Eigen::Vector3d>(t[0]);
      out.moment_Nm = nb::cast<Eigen::Vector3d>(t[1]);
      return 0;
    } catch (const std::exception& e) {
      try {
        msg_ = std::string("Python force element failed: ") + e.what();
      } catch (...) {
      }
      return -1;
    } catch (...) {  // nothing may cross the SUNDIALS callback
      return -1;
    }
  }
  std::string message() const override { return msg_; }
  bool thread_safe() const noexcept override { return false; }  // Python needs the GIL

 private:
  nb::callable f_;
  mutable std::string msg_;
};

nb::dict to_dict(const DynamicOutputs& o) {
  nb::dict d;
  d["time_s"] = o.time_s;
  d["inner_speed_rad_s"] = o.inner_speed_rad_s;
  d["cage_speed_rad_s"] = o.cage_speed_rad_s;
  d["drive_torque_Nm"] = o.drive_torque_Nm;
  d["outer_ring_torque_Nm"] = o.outer_ring_torque_Nm;
  nb::dict tq;
  for (int k = 0; k < 3; ++k) tq[kContactNames[k]] = o.torque_by_contact_Nm[k];
  d["torque_by_contact_Nm"] = tq;
  put_friction_by_contact(d, o.power_W, o.Lambda_min, o.phi_max);
  d["damping_power_W"] = o.damping_power_W;
  d["cage_power_W"] = o.cage_power_W;
  d["external_power_W"] = o.external_power_W;
  d["power_input_W"] = o.power_input_W;
  d["kinetic_energy_J"] = o.kinetic_energy_J;
  d["max_penetration_m"] = o.max_penetration_m;
  d["contact_work_W"] = o.contact_work_W;
  d["ring_force_N"] = Eigen::Vector3d(o.ring_force_N);
  d["ring_moment_Nm"] = Eigen::Vector3d(o.ring_moment_Nm);
  const size_t Z = o.rollers.size();
  std::vector<double> qo(Z), qi(Z), qr(Z), qc(Z), spin(Z), so(Z), si(Z), skew(Z), tilt(Z);
  for (size_t j = 0; j < Z; ++j) {
    const auto& r = o.rollers[j];
    qo[j] = r.outer_N;
    qi[j] = r.inner_N;
    qr[j] = r.rib_N;
    qc[j] = r.cage_N;
    spin[j] = r.spin_rad_s;
    so[j] = r.sliding_outer_m_s;
    si[j] = r.sliding_inner_m_s;
    skew[j] = r.skew_rad;
    tilt[j] = r.tilt_rad;
  }
  d["roller_outer_N"] = qo;
  d["roller_inner_N"] = qi;
  d["roller_rib_N"] = qr;
  d["roller_cage_N"] = qc;
  d["roller_spin_rad_s"] = spin;
  d["roller_sliding_outer_m_s"] = so;
  d["roller_sliding_inner_m_s"] = si;
  d["roller_skew_rad"] = skew;
  d["roller_tilt_rad"] = tilt;
  return d;
}

}  // namespace

void bind_dynamics(nb::module_& parent) {
  nb::module_ m = parent.def_submodule("dynamics", "Dynamic multibody simulation (SI units).");
  m.attr("QUADRATURE_COUNT") = kQuadratureCount;
  using V = DynamicValues;
  nb::class_<V>(m, "DynamicValues")
      .def(nb::init<>())
      .def_rw("roller_mass_kg", &V::roller_mass_kg)
      .def_rw("roller_inertia_axial_kgm2", &V::roller_inertia_axial_kgm2)
      .def_rw("roller_inertia_transverse_kgm2", &V::roller_inertia_transverse_kgm2)
      .def_rw("roller_com_offset_m", &V::roller_com_offset_m)
      .def_rw("cage_mass_kg", &V::cage_mass_kg)
      .def_rw("cage_inertia_axial_kgm2", &V::cage_inertia_axial_kgm2)
      .def_rw("cage_inertia_transverse_kgm2", &V::cage_inertia_transverse_kgm2)
      .def_rw("cage_pitch_radius_m", &V::cage_pitch_radius_m)
      .def_rw("cage_pocket_clearance_m", &V::cage_pocket_clearance_m)
      .def_rw("cage_pocket_axial_clearance_m", &V::cage_pocket_axial_clearance_m)
      .def_rw("cage_edge_height_m", &V::cage_edge_height_m)
      .def_rw("ring_mass_kg", &V::ring_mass_kg)
      .def_rw("ring_inertia_axial_kgm2", &V::ring_inertia_axial_kgm2)
      .def_rw("ring_inertia_transverse_kgm2", &V::ring_inertia_transverse_kgm2)
      .def_rw("damping_time_s", &V::damping_time_s)
      .def_rw("gravity_m_s2", &V::gravity_m_s2)
      .def_rw("cage_points", &V::cage_points)
      .def_rw("cage", &V::cage);
  nb::class_<RingDrive>(m, "RingDrive")
      .def(nb::init<>())
      .def_rw("time_s", &RingDrive::time_s)
      .def_rw("speed_rad_s", &RingDrive::speed_rad_s)
      .def_rw("axial_N", &RingDrive::axial_N)
      .def_rw("radial_N", &RingDrive::radial_N)
      .def_rw("load_time_s", &RingDrive::load_time_s)
      .def_rw("axial_profile_N", &RingDrive::axial_profile_N)
      .def_rw("radial_profile_N", &RingDrive::radial_profile_N)
      .def("axial", &RingDrive::axial, "time_s"_a)
      .def("radial", &RingDrive::radial, "time_s"_a)
      .def_rw("tilt_moment_x_Nm", &RingDrive::tilt_moment_x_Nm)
      .def_rw("tilt_moment_y_Nm", &RingDrive::tilt_moment_y_Nm)
      .def_rw("tilt_free", &RingDrive::tilt_free)
      .def_rw("free_x", &RingDrive::free_x)
      .def_rw("free_y", &RingDrive::free_y)
      .def_rw("free_z", &RingDrive::free_z)
      .def("speed", &RingDrive::speed, "time_s"_a);
  nb::class_<IntegratorSettings>(m, "IntegratorSettings")
      .def(nb::init<>())
      .def_rw("rtol", &IntegratorSettings::rtol)
      .def_rw("atol_position_m", &IntegratorSettings::atol_position_m)
      .def_rw("atol_axis", &IntegratorSettings::atol_axis)
      .def_rw("atol_velocity_m_s", &IntegratorSettings::atol_velocity_m_s)
      .def_rw("atol_rate_rad_s", &IntegratorSettings::atol_rate_rad_s)
      .def_rw("max_step_s", &IntegratorSettings::max_step_s)
      .def_rw("max_steps", &IntegratorSettings::max_steps)
      .def_rw("coloured_jacobian", &IntegratorSettings::coloured_jacobian)
      .def_rw("structured_linear_solver", &IntegratorSettings::structured_linear_solver)
      .def_rw("quadratures_in_state", &IntegratorSettings::quadratures_in_state)
      .def_rw("jacobian_max_age_steps", &IntegratorSettings::jacobian_max_age_steps)
      .def_rw("absolute_velocity_tolerance", &IntegratorSettings::absolute_velocity_tolerance)
      .def_rw("threads", &IntegratorSettings::threads);
  nb::class_<ForceElement>(m, "ForceElement");
  nb::class_<DragElementValues>(m, "DragElementValues")
      .def(nb::init<>())
      .def_rw("oil_density_kg_m3", &DragElementValues::oil_density_kg_m3)
      .def_rw("roller_drag_coefficient", &DragElementValues::roller_drag_coefficient)
      .def_rw("roller_frontal_area_m2", &DragElementValues::roller_frontal_area_m2)
      .def_rw("swirl_ratio", &DragElementValues::swirl_ratio)
      .def_rw("roller_spin_drag_Nms", &DragElementValues::roller_spin_drag_Nms)
      .def_rw("cage_drag_Nms", &DragElementValues::cage_drag_Nms)
      .def_rw("cage_drag_Nms2", &DragElementValues::cage_drag_Nms2);
  nb::class_<DragElement, ForceElement>(m, "DragElement")
      .def(nb::init<const DragElementValues&>(), "values"_a);
  nb::class_<PyForceElement, ForceElement>(m, "PythonForceElement",
                                           "callable(body, p, axis, v, w, time_s, inner_speed, cage_speed) -> "
                                           "(force_N, moment_Nm); body -1 = cage, j = roller j")
      .def(nb::init<nb::callable>(), "function"_a);
  nb::class_<DynamicModel>(m, "DynamicModel")
      .def(
          "__init__",
          [](DynamicModel* self, std::shared_ptr<BearingModel> b, const V& v, const FrictionParameters& f,
             const SurfacePair& race, const SurfacePair& rib, const ContactLubricantState& lub,
             const ContactLubricantState* outer_lub, const ContactLubricantState* inner_lub) {
            new (self) DynamicModel(std::move(b), v, f, race, rib, outer_lub ? *outer_lub : lub,
                                    inner_lub ? *inner_lub : lub);
          },
          "bearing"_a, "values"_a, "friction"_a, "raceway"_a, "rib"_a, "lubricant"_a,
          "outer_lubricant"_a.none() = nb::none(), "inner_lubricant"_a.none() = nb::none(),
          "lubricant: the contacts' lubricant state; outer_lubricant / inner_lubricant (default: lubricant) "
          "that of the outer ring's contacts and of the inner ring's (raceway and rib).")
      .def_prop_ro("state_size", &DynamicModel::state_size)
      .def_prop_ro("roller_count", &DynamicModel::roller_count)
      .def_prop_ro("cage_offset", &DynamicModel::cage_offset)
      .def_prop_ro("ring_offset", &DynamicModel::ring_offset)
      .def_prop_ro("slice_damping_Ns_m", [](const DynamicModel& d) { return d.slice_friction().values().d_max_Ns_m; })
      .def_prop_ro("pocket_damping_Ns_m", &DynamicModel::pocket_damping_Ns_m)
      .def_prop_ro("rib_damping_Ns_m", &DynamicModel::rib_damping_Ns_m)
      .def(
          "pocket_frame",
          [](const DynamicModel& d, int k) {
            Eigen::Vector3d c, x, y, z;
            d.pocket_frame(k, c, x, y, z);
            return nb::make_tuple(c, x, y, z);
          },
          "k"_a)
      .def("window_half_width_m", &DynamicModel::window_half_width_m, "y_m"_a);
  m.def(
      "initial_state",
      [](const DynamicModel& model, const BearingData& qs, double cage_speed, const std::vector<double>& spin) {
        const auto y = initial_state(model, qs, cage_speed, spin);
        return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(y.data(), y.size()));
      },
      "model"_a, "quasi_static"_a, "cage_speed_rad_s"_a, "roller_spin_rad_s"_a);
  m.def(
      "rhs",
      [](std::shared_ptr<DynamicModel> model, const RingDrive& drive, double t, const Eigen::VectorXd& y,
         std::vector<std::shared_ptr<ForceElement>> elements) {
        check_size("rhs: y", size_t(y.size()), size_t(model->state_size()));
        DynamicData data(*model);
        for (auto& e : elements) data.elements.push_back(e.get());
        Eigen::VectorXd f(y.size());
        DynamicOutputs out;
        const int st = dynamic_rhs(*model, data, drive, t, y.data(), f.data(), &out);
        return nb::make_tuple(st, f, to_dict(out));
      },
      "model"_a, "drive"_a, "time_s"_a, "y"_a, "elements"_a = std::vector<std::shared_ptr<ForceElement>>{},
      "Status, state derivative and outputs at (t, y).");
  m.def(
      "jacobian",
      [](std::shared_ptr<DynamicModel> model, const RingDrive& drive, double t, const Eigen::VectorXd& y) {
        const int N = model->state_size();
        check_size("jacobian: y", size_t(y.size()), size_t(N));
        DynamicData data(*model);
        Eigen::VectorXd f(N), work(2 * N);
        if (dynamic_rhs(*model, data, drive, t, y.data(), f.data()) != 0)
          throw std::runtime_error("jacobian: the state cannot be evaluated");
        Eigen::MatrixXd J(N, N);
        if (dynamic_jacobian(*model, data, drive, t, y.data(), f.data(), J.data(), work.data()) != 0)
          throw std::runtime_error("jacobian: evaluation failed");
        return J;
      },
      "model"_a, "drive"_a, "time_s"_a, "y"_a, "The coloured finite-difference Jacobian df/dy.");
  nb::class_<DynamicSimulation>(m, "DynamicSimulation")
      .def(
          "__init__",
          [](DynamicSimulation* self, std::shared_ptr<DynamicModel> m, const RingDrive& d, const IntegratorSettings& s,
             double t0, const std::vector<double>& y0) { new (self) DynamicSimulation(std::move(m), d, s, t0, y0); },
          "model"_a, "drive"_a, "settings"_a, "t0"_a, "y0"_a)
      .def("advance", &DynamicSimulation::advance, "t_end"_a, "Integrate to t_end; 0 = success.")
      .def_prop_ro("time_s", &DynamicSimulation::time)
      .def_prop_ro("state", [](const DynamicSimulation& s) {
        const auto y = s.state();
        return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(y.data(), y.size()));
      })
      .def_prop_ro("quadratures", [](const DynamicSimulation& s) {
        const auto q = s.quadratures();
        return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(q.data(), q.size()));
      })
      .def("set_quadrature_offset", &DynamicSimulation::set_quadrature_offset, "q0"_a)
      .def("outputs", [](DynamicSimulation& s) { return to_dict(s.outputs()); })
      .def_prop_ro("message", &DynamicSimulation::message)
      .def(
          "add_element", [](DynamicSimulation& s, std::shared_ptr<ForceElement> e) { s.add_element(std::move(e)); },
          "element"_a)
      .def_prop_ro("steps", &DynamicSimulation::steps)
      .def_prop_ro("rhs_evaluations", &DynamicSimulation::rhs_evaluations)
      .def_prop_ro("jacobian_evaluations", &DynamicSimulation::jacobian_evaluations)
      .def_prop_ro("last_step_s", &DynamicSimulation::last_step_s);
}

}  // namespace kegel::python
