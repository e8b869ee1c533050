#include "kegel/core/material.hpp"

#include "kegel/core/checks.hpp"

namespace kegel {

ElasticMaterial::ElasticMaterial(double E, double nu, double rho) : E_(E), nu_(nu), rho_(rho) {
  detail::require_positive("ElasticMaterial", "youngs_modulus_Pa", E);
  // Thermodynamic bounds of an isotropic solid: -1 < nu < 0.5.
  if (!(nu > -1.0 && nu < 0.5)) {
    detail::fail("ElasticMaterial", "poisson_ratio", nu, "a value in (-1, 0.5)");
  }
  detail::require_positive("ElasticMaterial", "density_kg_m3", rho);
}

double reduced_modulus_Pa(const ElasticMaterial& a, const ElasticMaterial& b) noexcept {
  const double ca = (1.0 - a.poisson_ratio() * a.poisson_ratio()) / a.youngs_modulus_Pa();
  const double cb = (1.0 - b.poisson_ratio() * b.poisson_ratio()) / b.youngs_modulus_Pa();
  return 2.0 / (ca + cb);
}

}  // namespace kegel
