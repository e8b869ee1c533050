// Per-slice friction of a roller/raceway line contact: every force and moment by mechanism
// (EHL sliding, EHL rolling, solid sliding, solid rolling, hysteresis, damping) and the film
// state, so that later outputs can explain a torque (seed paper, Section 2.1.3).
//
// Model / Data split: FrictionParameters and SurfacePair are the fixed model description
// (validated value types); ContactLubricantState is precomputed once per temperature;
// SliceInput is one slice's state; evaluate_slice() is a free, noexcept, allocation-free
// function (the hot loop).
//
// Contact frame of a slice: x = rolling (entrainment) direction, y = along the contact line,
// z = contact normal. Body 1 is the roller, body 2 the ring (or rib). Forces are those acting
// on body 1; body 2 receives the opposite.
#pragma once

#include "kegel/core/lubricant.hpp"
#include "kegel/core/tribology.hpp"

namespace kegel {

/// Friction-law parameters that the seed paper does not give (kegel/data/friction/*.toml cites
/// each one). Throws std::invalid_argument from the constructor on invalid values.
/// Thermal reduction of the EHL rolling resistance (inlet shear heating): none, Aihara's
/// phi_T = 1/(1 + 0.29 L^0.78) (default), or the Zhu-Cheng film-thickness factor of Eq. 12 (as
/// Zhou and Hoeprich 1991 apply it to the rolling force).
enum class RollingThermal { Off = 0, Aihara = 1, ZhuCheng = 2 };

class FrictionParameters {
 public:
  struct Values {
    double tau_L0_Pa = 0.0;        ///< limiting shear stress at p = 0 (Bair-Winer)
    double gamma_L = 0.0;          ///< limiting shear stress-pressure coefficient
    double mu_s = 0.0;             ///< peak solid friction coefficient (Eq. 21-27)
    double mu_d = 0.0;             ///< dynamic solid friction coefficient
    double v_s_m_s = 0.0;          ///< velocity of the peak
    double v_d_m_s = 0.0;          ///< velocity from which mu = mu_d
    double c_r = 0.0;              ///< solid rolling coefficient (Eq. 19), N^(1 - e_r) m
    double e_r = 1.0;              ///< solid rolling exponent (Eq. 19)
    double a_v = 0.0;              ///< hysteresis loss factor (Eq. 20)
    double d_max_Ns_m = 0.0;       ///< maximum damping coefficient per slice (Eq. 2)
    double delta_max_m = 1e-6;     ///< penetration of full damping (Eq. 2)
    double gold_C1_Pa_K2 = 0.0;    ///< Gold et al. (Eq. 9); 0 switches compression heating off
    double gold_C2_Pa_K = 0.0;     ///< Gold et al. (Eq. 9); 0 switches compression heating off
    RollingThermal rolling_thermal = RollingThermal::Aihara;  ///< thermal factor of the EHL rolling force
    /// Starvation of the raceway contacts' rolling resistance (Biboulet-Houpert Part 1, Eq. 44):
    /// the inlet oil gap over the fully flooded film, S >= 2; 0 = fully flooded. One value per
    /// raceway (the lubricant supply of kegel/supply.py: inner = cone, outer = cup).
    double inlet_gap_ratio_inner = 0.0;
    double inlet_gap_ratio_outer = 0.0;
    /// The contact / hydraulic boundary g [m]: the contact model owns the oil within film height
    /// g of each line contact, so its rolling force loses the far field of the film beyond g
    /// (tribology::rolling_force_beyond_film_N_m, between g and the supply's meniscus; nothing
    /// when the supply's meniscus lies within g, S_supply <= g / h, h the slice's isothermal
    /// flooded film). 0 = no cut-off.
    double contact_film_limit_m = 0.0;
  };
  /// True when Eq. 9 (compression heating of the contact lubricant) is active.
  bool compression_heating() const noexcept { return v_.gold_C1_Pa_K2 > 0.0 && v_.gold_C2_Pa_K > 0.0; }
  explicit FrictionParameters(const Values& v);
  const Values& values() const noexcept { return v_; }
  const tribology::CubicFrictionLaw& cubic_law() const noexcept { return law_; }

 private:
  Values v_;
  tribology::CubicFrictionLaw law_;
};

/// Roughness and mixed-friction constants of one contact pair (seed paper Table 4/A2).
class SurfacePair {
 public:
  SurfacePair(double sigma_m, double zhou_hoeprich_B, double zhou_hoeprich_C,
              double E_reduced_Pa);
  double sigma_m() const noexcept { return sigma_; }
  double B() const noexcept { return B_; }
  double C() const noexcept { return C_; }
  double E_reduced_Pa() const noexcept { return E_; }

 private:
  double sigma_, B_, C_, E_;
};

/// Lubricant quantities at one bulk temperature, precomputed outside the hot loop.
struct ContactLubricantState {
  double temperature_K = 0.0;
  double eta0_Pas = 0.0;                 ///< Eq. 8
  double alpha_p_1_Pa = 0.0;             ///< from Eq. 7 at p = 0
  double deta_dtheta_Pas_K = 0.0;        ///< Eq. 15
  double thermal_conductivity_W_mK = 0.0;
  double dicke_a_bar = 0.0;              ///< a1 + a2 theta (Eq. 7)
  double dicke_b = 0.0;                  ///< b1 + b2 theta (Eq. 7)
  // Parameters to re-evaluate Eq. 7-8 at the compression temperature of Eq. 9
  double vogel_K_Pas = 0.0, vogel_B_K = 0.0, vogel_C_degC = 0.0;
  double dicke_a1_bar = 0.0, dicke_a2_bar_per_K = 0.0, dicke_b1 = 0.0, dicke_b2_per_K = 0.0;
};

/// Evaluate the lubricant at a bulk temperature (throws std::invalid_argument outside the
/// lubricant's domain).
ContactLubricantState make_contact_lubricant_state(const Lubricant& lub, double temperature_K);

/// One slice's geometry, load and kinematics (contact frame, SI).
struct SliceInput {
  double load_N = 0.0;           ///< normal load Q on the slice (>= 0)
  double width_m = 0.0;          ///< slice width along the contact line
  double reduced_radius_m = 0.0; ///< R' in the rolling direction
  double u1_x_m_s = 0.0;         ///< roller surface velocity, rolling direction
  double u1_y_m_s = 0.0;         ///< roller surface velocity, along the contact line
  double u2_x_m_s = 0.0;         ///< ring surface velocity, rolling direction
  double u2_y_m_s = 0.0;         ///< ring surface velocity, along the contact line
  double penetration_m = 0.0;    ///< for the damping law (Eq. 2)
  double normal_velocity_m_s = 0.0;  ///< approach velocity, for damping (Eq. 1)
  bool outer_ring = false;       ///< a slice of the outer (cup) raceway: selects its inlet supply
};

/// Everything one slice contributes, by mechanism. Forces act on the roller (body 1).
struct SliceResult {
  bool in_contact = false;            ///< false for a slice without load: every value is 0
  // Hertz line contact of the slice
  double half_width_m = 0.0;          ///< b = sqrt(8 w R' / (pi E'))
  double max_pressure_Pa = 0.0;       ///< p0 = 2 w / (pi b)
  double mean_pressure_Pa = 0.0;      ///< w / (2 b), used for eta(p) and tau_L(p)
  double area_m2 = 0.0;               ///< A_Hertz = 2 b width
  // Film state
  double film_isothermal_m = 0.0;     ///< Moes h_c
  double thermal_factor = 1.0;        ///< Zhu-Cheng phi_theta (Eq. 12)
  double film_m = 0.0;                ///< h_th = phi_theta h_c (Eq. 11)
  double Lambda = 0.0;                ///< Eq. 30
  double phi = 1.0;                   ///< asperity load ratio, Eq. 29
  double contact_temperature_K = 0.0; ///< bulk, or after compression heating (Eq. 9)
  double eta_contact_Pas = 0.0;       ///< Dicke viscosity at the mean pressure (Eq. 7)
  double tau_L_Pa = 0.0;              ///< limiting shear stress at the mean pressure
  double tau_ehl_Pa = 0.0;            ///< |tau| of the lubricant (Eq. 4-6, 10)
  double mu_solid = 0.0;              ///< |mu(v_sl)| (Eq. 21-27)
  double sliding_speed_m_s = 0.0;     ///< |u1 - u2|
  double entrainment_speed_m_s = 0.0; ///< u_av = |u1_x + u2_x| / 2
  // Sliding forces in the contact plane (x, y), weighted by Eq. 36
  double F_ehl_sliding_N[2] = {0.0, 0.0};    ///< (1 - phi) tau A, against u1 - u2
  double F_solid_sliding_N[2] = {0.0, 0.0};  ///< phi mu Q, against u1 - u2
  // Rolling resistance (magnitudes; each opposes the rolling of both surfaces)
  double F_ehl_rolling_N = 0.0;       ///< (1 - phi) x thermal x starvation x Biboulet-Houpert (the seed's Eq. 16, corrected)
  double rolling_thermal_factor = 1.0;  ///< thermal factor applied to the EHL rolling force
  double rolling_starvation_factor = 1.0;  ///< EHL rolling force over its flooded value (supply and film limit)
  double inlet_gap_ratio = 0.0;       ///< the inlet's S: the supply's, or g / h where the film limit cuts; 0 = flooded
  double M_solid_rolling_Nm = 0.0;    ///< phi x Eq. 19
  double M_hysteresis_Nm = 0.0;       ///< Eq. 20 (material, not weighted)
  // Normal direction
  double F_damping_N = 0.0;           ///< Eq. 1, along +z on body 1 (opposes approach)
  // Dissipated power of the sliding mechanisms (F . (u1 - u2)), W
  double P_ehl_sliding_W = 0.0;
  double P_solid_sliding_W = 0.0;
};

/// One cell of the rib contact (cell model): its load, area and the principal relative radii of
/// the contact (Rx along the entrainment direction) for the elliptic film of Eq. 31-35.
struct CellInput {
  double load_N = 0.0;        ///< p * cell area
  double contact_load_N = 0.0;  ///< load of the whole rib contact (for W in Eq. 35); 0: load_N
  double area_m2 = 0.0;       ///< cell area
  double Rx_m = 0.0;          ///< reduced radius along the entrainment direction
  double Ry_m = 0.0;          ///< reduced radius across it
  double u1_x_m_s = 0.0, u1_y_m_s = 0.0;  ///< roller end surface velocity in the tangent plane
  double u2_x_m_s = 0.0, u2_y_m_s = 0.0;  ///< rib surface velocity
};

/// Evaluate one cell of the roller end / rib contact: elliptic film (Eq. 31-35) with the cell's
/// entrainment velocity but the load parameter W of the whole contact (the paper's W_{i,j} with
/// the cell's load makes h grow as cells shrink, h ~ n^0.134 for n x n cells, so the friction
/// would depend on the grid), the Zhu-Cheng factor, Lambda with the rib roughness, and the mixed
/// sliding friction (Eq. 4-10, 21-28, 36) at the cell's pressure. The rib contact is a sliding
/// ("drilling") contact: no rolling resistance, hysteresis or damping terms are evaluated.
void evaluate_cell(const CellInput& in, const SurfacePair& surfaces, const ContactLubricantState& lub,
                   const FrictionParameters& fp, SliceResult& out) noexcept;

/// Evaluate one slice (noexcept, allocation-free). A slice without load returns
/// in_contact = false and zeros; a slice without entrainment has no film (Lambda = 0, phi = 1).
void evaluate_slice(const SliceInput& in, const SurfacePair& surfaces,
                    const ContactLubricantState& lub, const FrictionParameters& fp,
                    SliceResult& out) noexcept;

}  // namespace kegel
