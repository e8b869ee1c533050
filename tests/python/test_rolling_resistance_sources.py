"""kegel's EHL rolling force (Biboulet-Houpert Part 1, the seed's Eq. 16 corrected) against
independent numerical EHL solutions: Zhou and Hoeprich, J. Tribol. 113 (1991) 590-597, Table 1
(isothermal line contacts in pure rolling, G = 3745; the numbers as transcribed in
kegel/data/validation/FORMULAS.md, section 4.2). R_e and E' of those solutions are not printed,
so only ratios are compared: how the force grows with speed and with load.

Zhou and Hoeprich's dimensionless groups are U = eta0 u / (E' R_e), W = w / (E' R_e); Biboulet and
Houpert's U carries a factor 2 (U_BH = 2 eta0 u_m / (E' R)), their W is the same."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kegel._core import tribology as t

# Table 1, block 2: W = 2.0e-4, G = 3745; U x 1e11 and the rolling moment 2 F_r0 R_e
ZH_U = np.array([1.0, 3.0, 10.0, 60.0, 100.0]) * 1e-11
ZH_U_MOMENT = np.array([0.0623, 0.1455, 0.3172, 0.8781, 1.1290])
# Table 1, block 1: U = 35.0e-11, G = 3745; W x 1e4 (first five rows) and 2 F_r0 R_e
ZH_W = np.array([1.0, 1.5, 2.0, 2.5, 3.0]) * 1e-4
ZH_W_MOMENT = np.array([0.5485, 0.6135, 0.6600, 0.7031, 0.6933])


def _bh(U_zh: float, W: float) -> float:
    return t.biboulet_houpert_line_force(2.0 * U_zh, W)


def test_speed_dependence_agrees_in_the_bearing_range():
    """At the raceway contacts of the paper's bearings U is 4e-11 ... 4e-10 (Zhou-Hoeprich's
    definition). From U = 1e-11 to 1e-10 the force grows 5.09-fold in Zhou-Hoeprich's solutions
    and 5.62-fold in kegel (+10 %); towards 1e-9 kegel grows faster (U^0.75 against U^0.62:
    31.6-fold against 18.1-fold from 1e-11)."""
    bh = np.array([_bh(U, 2.0e-4) for U in ZH_U])
    r_zh, r_bh = ZH_U_MOMENT[2] / ZH_U_MOMENT[0], bh[2] / bh[0]
    assert r_zh == pytest.approx(5.09, abs=0.01)
    assert r_bh / r_zh - 1.0 == pytest.approx(0.104, abs=0.02)
    slope_zh = np.polyfit(np.log(ZH_U), np.log(ZH_U_MOMENT), 1)[0]
    slope_bh = np.polyfit(np.log(ZH_U), np.log(bh), 1)[0]
    assert slope_zh == pytest.approx(0.622, abs=0.005) and slope_bh == pytest.approx(0.75, abs=0.005)
    # the implied E' R_e^2 (constant if both agreed) stays within 12 % of steel with R_e = 3 mm
    # (2.08e6 N) up to U = 1e-10
    implied = ZH_U_MOMENT / (2.0 * bh)
    assert np.all(np.abs(implied[:3] / (2.3077e11 * 3e-3 ** 2) - 1.0) < 0.12)


def test_load_dependence_differs():
    """Zhou-Hoeprich's solutions grow by 26 % from W = 1e-4 to 3e-4 (their fit: W^0.246); kegel's
    Biboulet-Houpert force does not depend on the load in the EHL regime (+0.02 %). This is the
    difference that makes kegel's torque fall under a growing radial load where the SKF model's and
    Aihara's (load exponent 0.31, from measured bearings) rise: see docs/validation.md."""
    bh = np.array([_bh(35e-11, W) for W in ZH_W])
    assert ZH_W_MOMENT[-1] / ZH_W_MOMENT[0] == pytest.approx(1.264, abs=0.001)
    assert bh[-1] / bh[0] == pytest.approx(1.0, abs=0.001)


@pytest.mark.xfail(strict=True, reason="Biboulet-Houpert's EHL rolling force is load-independent; Zhou-Hoeprich's "
                                       "numerical solutions grow as W^0.25 (docs/validation.md)")
def test_load_dependence_within_ten_percent_of_the_numerical_solutions():
    bh = np.array([_bh(35e-11, W) for W in ZH_W])
    np.testing.assert_allclose(bh / bh[0], ZH_W_MOMENT / ZH_W_MOMENT[0], rtol=0.10)
