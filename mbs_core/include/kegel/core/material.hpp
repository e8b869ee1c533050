// Elastic solid material (rings, rollers, cage) as a validated value type.
#pragma once

namespace kegel {

class ElasticMaterial {
 public:
  /// Throws std::invalid_argument unless E > 0, -1 < nu < 0.5 and density > 0.
  ElasticMaterial(double youngs_modulus_Pa, double poisson_ratio, double density_kg_m3);

  double youngs_modulus_Pa() const noexcept { return E_; }
  double poisson_ratio() const noexcept { return nu_; }
  double density_kg_m3() const noexcept { return rho_; }

 private:
  double E_;
  double nu_;
  double rho_;
};

/// Reduced modulus of a contact pair, E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) [Pa]
/// (the E' of the seed paper, Eq. 12, 16-18, 33-35; 230.8 GPa for steel on steel).
double reduced_modulus_Pa(const ElasticMaterial& a, const ElasticMaterial& b) noexcept;

}  // namespace kegel
