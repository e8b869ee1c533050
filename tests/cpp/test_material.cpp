#include <gtest/gtest.h>

#include <stdexcept>

#include "kegel/core/material.hpp"

TEST(Material, ReducedModulusSteelOnSteel) {
  const kegel::ElasticMaterial steel(210e9, 0.3, 7850.0);
  // known_values.md: E' = 230.8 GPa for E = 210 GPa, nu = 0.3; by hand 210 / 0.91 GPa.
  EXPECT_NEAR(kegel::reduced_modulus_Pa(steel, steel), 210e9 / 0.91, 1.0);
  EXPECT_NEAR(kegel::reduced_modulus_Pa(steel, steel) / 1e9, 230.8, 0.05);
}

TEST(Material, ReducedModulusIsSymmetric) {
  const kegel::ElasticMaterial a(210e9, 0.3, 7850.0);
  const kegel::ElasticMaterial b(310e9, 0.26, 3200.0);  // silicon nitride
  EXPECT_DOUBLE_EQ(kegel::reduced_modulus_Pa(a, b), kegel::reduced_modulus_Pa(b, a));
}

TEST(Material, RejectsInvalidValues) {
  EXPECT_THROW(kegel::ElasticMaterial(-1.0, 0.3, 7850.0), std::invalid_argument);
  EXPECT_THROW(kegel::ElasticMaterial(210e9, 0.5, 7850.0), std::invalid_argument);
  EXPECT_THROW(kegel::ElasticMaterial(210e9, 0.3, 0.0), std::invalid_argument);
}
