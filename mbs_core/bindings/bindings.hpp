// One binding file per C++ area; module.cpp assembles them into kegel._core.
#pragma once

#include <nanobind/nanobind.h>

namespace kegel::python {
void bind_lubricant(nanobind::module_& m);
void bind_material(nanobind::module_& m);
void bind_tribology(nanobind::module_& m);
void bind_contact(nanobind::module_& m);
void bind_quasi_static(nanobind::module_& m);
void bind_dynamics(nanobind::module_& m);
}  // namespace kegel::python
