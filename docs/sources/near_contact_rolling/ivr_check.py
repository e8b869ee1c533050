# Rigid isoviscous cylinder (reduced radius R) on plane, pure rolling, both surfaces at u_m, fully flooded.
# Reynolds: d/dx(h^3 dp/dx) = 12 eta u_m dh/dx, h = h0 + x^2/(2R)
# Once integrated: dp/dx = 12 eta u_m (h - hc)/h^3. Substitute x = sqrt(2 R h0) tan(th), h = h0/cos^2(th)
# Pure python, theta-midpoint quadrature.
import math
N = 200000
def integ(f, a, b):
    h = (b-a)/N; return sum(f(a+(i+0.5)*h) for i in range(N))*h
# dimensionless pressure P(th) = int_{-pi/2}^{th} (cos^2 - (1+c^2) cos^4) dth'  (dxi/(1+xi^2)^n = cos^{2n-2} dth)
def Pan(c, th):
    # analytic: int cos^2 = th/2 + sin2th/4 ; int cos^4 = 3th/8 + sin2th/4 + sin4th/32
    F2 = lambda t: t/2 + math.sin(2*t)/4
    F4 = lambda t: 3*t/8 + math.sin(2*t)/4 + math.sin(4*t)/32
    a = -math.pi/2
    return (F2(th)-F2(a)) - (1+c*c)*(F4(th)-F4(a))
# Reynolds BC: P(thc)=0 with c = tan(thc), thc>0
lo, hi = 0.05, 1.2
for _ in range(200):
    mid = 0.5*(lo+hi)
    if Pan(math.tan(mid), mid) > 0: lo = mid
    else: hi = mid
thc = 0.5*(lo+hi); c = math.tan(thc)
print("Reynolds BC: xi_c = x_c/sqrt(2 R h0) = %.5f ; h_c/h0 = %.5f" % (c, 1+c*c))
# load w = 12 eta u sqrt(2Rh0)/h0^2 * sqrt(2Rh0) * int P dxi = 24 eta u R/h0 * int P(th)/cos^2 dth
Wn = integ(lambda t: Pan(c,t)/math.cos(t)**2, -math.pi/2, thc)
print("load per unit length  w = %.4f * eta*u_m*R/h0" % (24*Wn))
# Poiseuille wall shear (pure rolling) tau = (h/2) dp/dx ; BH: F_t^x = -(1/2) int h dp/dx dx
# h dp/dx dx = 12 eta u/h0 * (xi^2-c^2)/(1+xi^2)^2 * sqrt(2Rh0) dxi = 12 eta u sqrt(2R/h0) (sin^2 - c^2 cos^2) dth
Fn = integ(lambda t: math.sin(t)**2 - c*c*math.cos(t)**2, -math.pi/2, thc)
fc = -0.5*12*math.sqrt(2)*Fn
print("rolling (Poiseuille) force per unit length on each surface f = %.4f * eta*u_m*sqrt(R/h0)" % fc)
wc = 24*Wn
print("BH2010 IVR 1.42*E'R*sqrt(U W) with this w: f = %.4f * eta*u_m*sqrt(R/h0)  (Dowson 1.46 -> %.4f)" % (1.42*math.sqrt(2*wc), 1.46*math.sqrt(2*wc)))
print("exact coefficient in BH form: f/(E'R sqrt(UW)) = %.4f" % (fc/math.sqrt(2*wc)))
# horizontal pressure force (BH eq 32: F_n^x = 2 F_t^x) -> total horizontal force on roller = f (BH eq 33)
# Half-Sommerfeld: full-Sommerfeld hc (c^2 = 1/3), negative pressures discarded
cS = 1/math.sqrt(3)
WnS = integ(lambda t: max(Pan(cS,t),0)/math.cos(t)**2, -math.pi/2, math.pi/2)
print("half-Sommerfeld load w = %.4f * eta u R/h0" % (24*WnS))
FnS = integ(lambda t: math.sin(t)**2 - cS*cS*math.cos(t)**2, -math.pi/2, 0)
print("half-Sommerfeld (Poiseuille integrated over positive-pressure half only) f = %.4f eta u sqrt(R/h0)" % (-0.5*12*math.sqrt(2)*FnS))
FnF = integ(lambda t: math.sin(t)**2 - cS*cS*math.cos(t)**2, -math.pi/2, math.pi/2)
print("full-Sommerfeld f (whole domain) = %.4f" % (-0.5*12*math.sqrt(2)*FnF))
