# Rigid isoviscous cylinder, pure rolling, gap h = h0(1+xi^2), x = sqrt(2 R h0) xi.
# Inlet meniscus at xi_a (p=0), Reynolds (Swift-Stieber) outlet at xi_c (p=dp/dx=0).
# Reports per-surface Poiseuille rolling force f = C_f * eta*u_m*sqrt(R/h0) and load w = C_w * eta*u_m*R/h0.
import math
def F2(t): return t/2 + math.sin(2*t)/4
def F4(t): return 3*t/8 + math.sin(2*t)/4 + math.sin(4*t)/32
def P(c, ta, t): return (F2(t)-F2(ta)) - (1+c*c)*(F4(t)-F4(ta))
def solve(ta):
    lo, hi = 1e-6, 1.5
    for _ in range(200):
        m = 0.5*(lo+hi)
        if P(math.tan(m), ta, m) > 0: lo = m
        else: hi = m
    tc = 0.5*(lo+hi); c = math.tan(tc)
    N = 40000
    hstep = (tc-ta)/N
    Wn = sum(P(c, ta, ta+(i+0.5)*hstep)/math.cos(ta+(i+0.5)*hstep)**2 for i in range(N))*hstep
    # int (sin^2 - c^2 cos^2) dth analytic
    G = lambda t: (t/2 - math.sin(2*t)/4) - c*c*(t/2 + math.sin(2*t)/4)
    Fn = G(tc) - G(ta)
    return c, 24*Wn, -6*math.sqrt(2)*Fn
print(" xi_a     S=h_a/h0   xi_c    C_w(load)  C_f(force)  f/f_flooded")
cw0 = None
res = []
for xa in [-1e6, -100, -30, -10, -5, -3, -2, -1.5, -1.0, -0.7, -0.5]:
    ta = math.atan(xa)
    c, cw, cf = solve(ta)
    res.append((xa, 1+xa*xa, c, cw, cf))
cf0 = res[0][4]
for xa, S, c, cw, cf in res:
    print("%8.1f %10.1f %7.4f %9.4f %10.4f %8.3f" % (xa, S, c, cw, cf, cf/cf0))
