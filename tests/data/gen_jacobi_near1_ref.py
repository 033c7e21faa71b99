"""Generate jacobi_near1_ref.csv: sn, cn, dn, D(u) = int_0^u sn^2 and the k-derivatives
of cn and D at 30 digits with mpmath, for moduli within 1e-4 .. 1e-15 of 1 and
arguments across the plateau (sn ~ 1, cn ~ dn ~ 2 e^-u tiny) up to past the quarter
period K ~ ln(4/k'), where one-point evaluation is hardest (tests/c/test_core.c
checks cn, dn relative there, not only absolute).

Independent of the library's method: sn, cn, dn from mpmath.ellipfun (theta
functions); D = (u - E(am u | m)) / m with the continuous amplitude for k < 1 and,
for k > 1, D(u, k) = k^-3 D(k u, 1/k) from sn(u, k) = sn(k u, 1/k) / k (checked
below against quadrature), at k = 1 tanh, sech and u - tanh; derivatives in k by
mpmath.diff at 60 digits (at k = 1 through both families, k < 1 and k > 1).
Arguments are the binary64 numbers nearest the listed decimals (what the C test
reads). Run: python3 tests/data/gen_jacobi_near1_ref.py > tests/data/jacobi_near1_ref.csv
"""
import mpmath as mp

mp.mp.dps = 60
KS = ["0.9999", "0.99999999", "0.999999999999999", "1", "1.000000000000001", "1.00000001"]
US = ["0.5", "3", "6", "9.1", "12", "15.5", "18.3", "21", "27.7", "-8"]


def core(u, k):
    """sn, cn, dn, D for 0 < k < 1."""
    m = k * k
    sn, cn, dn = (mp.ellipfun(kind, u, m=m) for kind in ("sn", "cn", "dn"))
    K = mp.ellipk(m)
    n = mp.floor((u + K) / (2 * K))
    am = n * mp.pi + mp.atan2((-1) ** int(n) * sn, (-1) ** int(n) * cn)
    return sn, cn, dn, (u - mp.ellipe(am, m)) / m


def values(u, k):
    if k == 1:
        return mp.tanh(u), mp.sech(u), mp.sech(u), u - mp.tanh(u)
    if k < 1:
        return core(u, k)
    s, c, d, D = core(k * u, 1 / k)
    return s / k, d, c, D / k ** 3


def check_D(u, k):
    D = values(u, k)[3]
    Q = mp.quad(lambda t: values(t, k)[0] ** 2, mp.linspace(0, u, 40))
    assert abs(D - Q) < mp.mpf(10) ** -25 * (1 + abs(D)), (u, k, D, Q)


check_D(mp.mpf(9), mp.mpf(float("1.00000001")))
check_D(mp.mpf(9), mp.mpf(float("0.99999999")))
print("k,u,sn,cn,dn,D,dcn_dk,dD_dk")
for ks in KS:
    for us in US:
        k, u = mp.mpf(float(ks)), mp.mpf(float(us))
        sn, cn, dn, D = values(u, k)
        dcn = mp.diff(lambda kk: values(u, kk)[1], k)
        dD = mp.diff(lambda kk: values(u, kk)[3], k)
        print(",".join([ks, us] + [mp.nstr(v, 30) for v in (sn, cn, dn, D, dcn, dD)]), flush=True)
