// One binding file per C++ area; module.cpp assembles them into kegel._core.
#pragma once

#include <nanobind/nanobind.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace kegel::python {
void bind_lubricant(nanobind::module_& m);
void bind_material(nanobind::module_& m);
void bind_tribology(nanobind::module_& m);
void bind_contact(nanobind::module_& m);
void bind_quasi_static(nanobind::module_& m);
void bind_dynamics(nanobind::module_& m);

/// A vector argument of the wrong length: "<what>: <got> values: expected <expected>".
inline void check_size(const char* what, std::size_t got, std::size_t expected) {
  if (got != expected) {
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(got) + " values: expected " +
                                std::to_string(expected));
  }
}

/// Contact and mechanism names of the friction outputs (BearingFriction's order).
inline constexpr const char* kContactNames[3] = {"outer_raceway", "inner_raceway", "rib"};
inline constexpr const char* kMechanismNames[5] = {"ehl_sliding", "solid_sliding", "ehl_rolling", "solid_rolling",
                                                   "hysteresis"};

/// d["power_W"][contact][mechanism], d["Lambda_min"][contact], d["phi_max"][contact], shared by the
/// quasi-static and the dynamic outputs.
inline void put_friction_by_contact(nanobind::dict& d, const double (&power_W)[3][5], const double (&Lambda_min)[3],
                                    const double (&phi_max)[3]) {
  nanobind::dict p, lam, phi;
  for (int k = 0; k < 3; ++k) {
    nanobind::dict row;
    for (int q = 0; q < 5; ++q) row[kMechanismNames[q]] = power_W[k][q];
    p[kContactNames[k]] = row;
    lam[kContactNames[k]] = Lambda_min[k];
    phi[kContactNames[k]] = phi_max[k];
  }
  d["power_W"] = p;
  d["Lambda_min"] = lam;
  d["phi_max"] = phi;
}
}  // namespace kegel::python
