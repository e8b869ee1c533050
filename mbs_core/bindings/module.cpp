#include <nanobind/stl/string.h>

#include "bindings.hpp"
#include "kegel/core/build_info.hpp"

namespace nb = nanobind;

NB_MODULE(_core, m) {
  m.doc() = "kegel's C++ core (mbs_core): SI units in and out; invalid input raises ValueError.";
  m.def("core_version", &kegel::core_version, "Version of the C++ core.");
  m.def("eigen_version", &kegel::eigen_version, "Eigen version the core was built with.");
  m.def("sundials_version", &kegel::sundials_version, "Version of the linked SUNDIALS library.");
  kegel::python::bind_lubricant(m);
  kegel::python::bind_material(m);
  kegel::python::bind_tribology(m);
  kegel::python::bind_contact(m);
  kegel::python::bind_quasi_static(m);
  kegel::python::bind_dynamics(m);
}
