"""Generate hermite_chain_ref.txt: points of exact Hermite elasticae near the separatrix
(the ones el_hermite_solve returns as chains, issue 12), at 90 digits with mpmath, for
tests/c/test_hermite.c (chains_lie_on_the_exact_curve).

Problems: p0 = 0, t0 = (0, 1), |p1| = 1, random p1, t1, sigma |p1|^2 log-uniform in
[300, 1e4] (numpy seed 12). The library gives the starting values (kappa0 and length
of every chain it returns, kappa0' of its first piece); the solution itself is then
found independently: Newton at 90 digits on (kappa0, ln(side (|F| - sigma)), L) for the
end point and end tangent (|F| - sigma first from the distance 2K between the
loops that the chain's phases carry), the curve from the first integrals, kappa(s) - kappa0 = det(x(s), F) / 2
and E(s) = int kappa^2 = <F, x(s)> + sigma s (F = (-2 kappa0', kappa0^2 - sigma), the
constant force), with kappa and E in closed form (mpmath.ellipfun, ellipe): for
|F| > sigma kappa = kappa_m cn(sqrt(|F|/2) s + q; k), k^2 = (|F| + sigma) / (2 |F|);
else kappa = +-kappa_m dn(v; m), v = sqrt((|F| + sigma)/4) s + q_v, m = 2 |F| / (|F| + sigma).
Each line: P1 P2 V1 V2 sigma L kappa0 npieces, then x y at s = j L / 10, j = 0..10.
Run: LIBELASTICA_PATH=build/libelastica.so PYTHONPATH=python \\
     python3 tests/data/gen_hermite_chain_ref.py > tests/data/hermite_chain_ref.txt
"""
import mpmath as mp
import numpy as np

import libelastica as el

mp.mp.dps = 90


def curve(k0, k0p, sigma):
    """s -> (x, y) of the elastica from 0 with tangent (0, 1), curvature k0, k0'."""
    F1, F2 = -2 * k0p, k0 * k0 - sigma
    Fn = mp.sqrt(F1 * F1 + F2 * F2)
    km2 = Fn + sigma
    km = mp.sqrt(km2)
    if Fn > sigma:
        m, scale, sign = km2 / (2 * Fn), mp.sqrt(Fn / 2), 1
        cn = k0 / km
        sn = -mp.sign(k0p) * mp.sqrt(1 - cn * cn)
    else:
        m, scale, sign = 2 * Fn / km2, km / 2, mp.sign(k0)
        dn = abs(k0) / km
        sn = -mp.sign(k0p * sign) * mp.sqrt((1 - dn * dn) / m)
        cn = mp.sqrt(1 - sn * sn)
    q = mp.ellipf(mp.atan2(sn, cn), m)
    K, Ec = mp.ellipk(m), mp.ellipe(m)

    def eps(u):                                  # int_0^u dn^2 (parameter m)
        n = mp.floor((u + K) / (2 * K))
        ur = u - 2 * n * K
        return mp.ellipe(mp.atan2(mp.ellipfun("sn", ur, m), mp.ellipfun("cn", ur, m)), m) + 2 * n * Ec

    def at(s):
        u = scale * s + q
        if Fn > sigma:                           # int cn^2 = (eps - (1 - m) u) / m
            kap = km * mp.ellipfun("cn", u, m)
            E = km2 / scale * ((eps(u) - (1 - m) * u) - (eps(q) - (1 - m) * q)) / m
        else:
            kap = sign * km * mp.ellipfun("dn", u, m)
            E = km2 / scale * (eps(u) - eps(q))
        a, b = E - sigma * s, -2 * (kap - k0)
        return (a * F1 - b * F2) / Fn ** 2, (a * F2 + b * F1) / Fn ** 2
    return at


def state(v, sigma, side, slope_sign):
    """kappa0, kappa0' of the unknowns v = (kappa0, y, L): |F| - sigma = side e^y (the
    coordinate in which the solutions near the separatrix are well conditioned), the
    sign of kappa0' given."""
    k0, y, L = v
    Fn = sigma + side * mp.exp(y)
    d = Fn * Fn - (k0 * k0 - sigma) ** 2
    if not d > 0:
        raise ValueError("no state")
    return k0, slope_sign * mp.sqrt(d) / 2


def residual(v, P, V, sigma, side, slope_sign):
    k0, k0p = state(v, sigma, side, slope_sign)
    at = curve(k0, k0p, sigma)
    L, h = v[2], mp.mpf("1e-40")
    x, y = at(L)
    xa, ya = at(L - h)
    xb, yb = at(L + h)
    th = mp.atan2(yb - ya, xb - xa) - mp.atan2(V[1], V[0])
    th = th - 2 * mp.pi * mp.nint(th / (2 * mp.pi))
    return mp.matrix([x - P[0], y - P[1], th])


def start_y(c, sigma, side):
    """ln|(|F| - sigma)| of a chain, from the distance 2K between the loops its first two
    pieces carry in their phases (the chain's own approximation, ~1e-8 relative)."""
    a, b = c.pieces[0], c.pieces[1]
    ka, kb = max(1, abs(a.k)), max(1, abs(b.k))      # phases in v = |k| u for loops
    K = (ka * (mp.mpf(a.q) + mp.sqrt(a.mu) * a.length) - kb * mp.mpf(b.q)) / 2
    mc = mp.findroot(lambda t: mp.ellipk(1 - mp.exp(t)) - K, mp.log(16) - 2 * K)   # ln(1 - m)
    Fn = 2 * mp.mpf(a.mu)
    return mp.log(2 * Fn) + mc if side > 0 else mp.log(Fn + sigma) + mc


def newton(k0, y, L, P, V, sigma, side, slope_sign):
    """The solution near (kappa0, y, L): damped Newton, central differences."""
    args = (P, V, sigma, side, slope_sign)
    v = mp.matrix([k0, y, L])
    for _ in range(40):
        r = residual(v, *args)
        if mp.norm(r) < mp.mpf("1e-35"):
            return v
        J = mp.matrix(3, 3)
        for j in range(3):
            h = mp.mpf("1e-25") * (1 + abs(v[j]))        # the angle residual is good to ~1e-40
            w1, w2 = v.copy(), v.copy()
            w1[j] += h
            w2[j] -= h
            J[:, j] = (residual(w1, *args) - residual(w2, *args)) / (2 * h)
        step = mp.lu_solve(J, -r)
        lam = 1
        while lam > 1e-6 and mp.norm(residual(v + lam * step, *args)) >= mp.norm(r):
            lam /= 2
        v = v + lam * step
    raise RuntimeError("Newton did not converge")


def first_slope(c):
    """kappa'(0) of a chain's first piece (SmoothElastica parameters, closed form)."""
    k, mu, q = mp.mpf(c.k), mp.mpf(c.mu), mp.mpf(c.q)
    if abs(k) <= 1:
        return -2 * k * mu * mp.ellipfun("sn", q, k * k) * mp.ellipfun("dn", q, k * k)
    v, m = abs(k) * q, 1 / (k * k)
    return -2 * k * mu * mp.ellipfun("sn", v, m) * mp.ellipfun("cn", v, m) / abs(k)


def main():
    rng = np.random.default_rng(12)
    nprob = 0
    while nprob < 10:
        a, b = rng.uniform(-np.pi, np.pi, 2)
        sigma = float(300.0 * (1e4 / 300.0) ** rng.uniform())
        P, V = (float(np.cos(a)), float(np.sin(a))), (float(np.cos(b)), float(np.sin(b)))
        chains = [c for c in el.hermite((0.0, 0.0), (0.0, 1.0), P, V, tension=sigma)
                  if isinstance(c, el.HermiteChain)]
        if not chains:
            continue
        nprob += 1
        for c in chains:
            side = 1 if c.has_inflection else -1     # an inflectional chain: |F| > sigma
            sg = mp.sign(first_slope(c.pieces[0]))
            y = start_y(c, mp.mpf(sigma), side)
            v = newton(mp.mpf(c.kappa0), y, mp.mpf(c.length), P, V, mp.mpf(sigma), side, sg)
            at = curve(*state(v, mp.mpf(sigma), side, sg), mp.mpf(sigma))
            pts = [at(v[2] * j / 10) for j in range(11)]
            print(" ".join(repr(x) for x in P + V + (sigma, float(v[2]), float(v[0]), len(c.pieces))) + " "
                  + " ".join(mp.nstr(z, 20) for p in pts for z in p))


if __name__ == "__main__":
    main()
