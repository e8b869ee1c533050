// Lubricant properties against ../shared/reference/known_values.md (FVA No. 3, Table A1) and
// against hand calculations.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "kegel/core/lubricant.hpp"
#include "test_data.hpp"

namespace {

double K(double degC) { return degC + 273.15; }

void expect_rel(double value, double ref, double rel) {
  EXPECT_NEAR(value, ref, std::abs(ref) * rel) << "value " << value << " vs reference " << ref;
}

}  // namespace

TEST(Lubricant, KnownValuesFVA3) {
  const kegel::Lubricant lub(kegel::test::fva3());
  // theta, eta0 [mPa s], rho [kg/m3], nu [mm2/s], alpha_p0 [1/GPa]; tolerance 0.5 %.
  struct Row { double theta, eta0, rho, nu, alpha; };
  for (const Row& r : {Row{40, 84.5, 872.6, 96.9, 22.4}, Row{50, 52.5, 866.6, 60.6, 21.0},
                       Row{100, 9.9, 836.6, 11.8, 16.0}}) {
    SCOPED_TRACE(r.theta);
    expect_rel(kegel::viscosity_ambient_Pas(lub, K(r.theta)) * 1e3, r.eta0, 5e-3);
    expect_rel(kegel::density_kg_m3(lub, K(r.theta)), r.rho, 5e-3);
    expect_rel(kegel::kinematic_viscosity_m2_s(lub, K(r.theta)) * 1e6, r.nu, 5e-3);
    expect_rel(kegel::pressure_viscosity_coefficient_per_Pa(lub, K(r.theta)) * 1e9, r.alpha,
               5e-3);
  }
}

TEST(Lubricant, HandCalculationAt50C) {
  const kegel::Lubricant lub(kegel::test::fva3());
  // Eq. 8 by hand: 0.062 mPa s * exp(1021.7 / 151.5517).
  const double eta0 = 0.062e-3 * std::exp(1021.7 / (50.0 + 101.5517));
  EXPECT_DOUBLE_EQ(kegel::viscosity_ambient_Pas(lub, K(50)), eta0);
  // Eq. 7 by hand at 1 GPa = 10000 bar.
  const double den = 327.7918 + 2.9862 * 50 + (4.419e-3 + 3.0115e-4 * 50) * 1e4;
  EXPECT_NEAR(kegel::viscosity_Pas(lub, K(50), 1e9), eta0 * std::exp(1e4 / den), 1e-12 * eta0 * std::exp(1e4 / den));
}

TEST(Lubricant, DickeReducesToVogelAtZeroPressure) {
  const kegel::Lubricant lub(kegel::test::fva3());
  for (double theta : {20.0, 50.0, 120.0}) {
    EXPECT_DOUBLE_EQ(kegel::viscosity_Pas(lub, K(theta), 0.0),
                     kegel::viscosity_ambient_Pas(lub, K(theta)));
  }
}

TEST(Lubricant, PressureViscosityCoefficientMatchesFiniteDifference) {
  const kegel::Lubricant lub(kegel::test::fva3());
  for (double theta : {30.0, 50.0, 90.0}) {
    const double T = K(theta);
    const double dp = 1e3;  // Pa
    const double fd =
        (std::log(kegel::viscosity_Pas(lub, T, dp)) - std::log(kegel::viscosity_Pas(lub, T, 0.0))) / dp;
    expect_rel(kegel::pressure_viscosity_coefficient_per_Pa(lub, T), fd, 1e-5);
  }
}

TEST(Lubricant, ViscosityFallsWithTemperatureAndRisesWithPressure) {
  const kegel::Lubricant lub(kegel::test::fva3());
  double last = INFINITY;
  for (double theta = -20; theta <= 150; theta += 10) {
    const double eta = kegel::viscosity_ambient_Pas(lub, K(theta));
    EXPECT_LT(eta, last);
    last = eta;
  }
  EXPECT_GT(kegel::viscosity_Pas(lub, K(50), 5e8), kegel::viscosity_Pas(lub, K(50), 1e8));
}

TEST(Lubricant, RejectsBadParametersWithNamedField) {
  auto p = kegel::test::fva3();
  p.vogel_K_Pas = -1.0;
  try {
    kegel::Lubricant lub(p);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("vogel_K_Pas"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("> 0"), std::string::npos) << e.what();
  }
  p = kegel::test::fva3();
  p.thermal_conductivity_W_mK = NAN;
  EXPECT_THROW(kegel::Lubricant{p}, std::invalid_argument);
}

TEST(Lubricant, RejectsTemperatureBelowVogelPole) {
  const kegel::Lubricant lub(kegel::test::fva3());
  EXPECT_THROW(kegel::check_temperature(lub, K(-101.6)), std::invalid_argument);
  EXPECT_THROW(kegel::check_temperature(lub, NAN), std::invalid_argument);
  EXPECT_NO_THROW(kegel::check_temperature(lub, K(50)));
  EXPECT_THROW(kegel::check_pressure(lub, K(50), -1.0), std::invalid_argument);
}
