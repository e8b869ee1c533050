#include "bindings.hpp"
#include "kegel/core/material.hpp"

namespace nb = nanobind;
using namespace nb::literals;

namespace kegel::python {

void bind_material(nb::module_& m) {
  nb::class_<ElasticMaterial>(m, "ElasticMaterial", "Isotropic elastic solid (checked).")
      .def(nb::init<double, double, double>(), "youngs_modulus_Pa"_a, "poisson_ratio"_a,
           "density_kg_m3"_a)
      .def_prop_ro("youngs_modulus_Pa", &ElasticMaterial::youngs_modulus_Pa)
      .def_prop_ro("poisson_ratio", &ElasticMaterial::poisson_ratio)
      .def_prop_ro("density_kg_m3", &ElasticMaterial::density_kg_m3);
  m.def("reduced_modulus_Pa", &reduced_modulus_Pa, "a"_a, "b"_a,
        "E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2).");
}

}  // namespace kegel::python
