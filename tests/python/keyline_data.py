"""Generated keyline data for tests and benchmarks (seed 000 §5): a realistic 3D
pantile keyline -- a planar curve with one global inflection made of two
different smooth elasticae joined there, placed on a tilted plane, sampled at
irregular arc lengths, with Gaussian noise.

Independent of libelastica (numpy + scipy.special only), so it can check the
library. Each side is an inflectional elastica (k < 1) in the parametrisation
of DESIGN.md / seed 000 (4.3):
    u = sqrt(mu) s + q,  sin((theta-phi)/2) = k sn(u),  cos((theta-phi)/2) = dn(u),
    kappa = 2 k sqrt(mu) cn(u),
    gamma(s) = gamma(0) + R(phi) ((2 (E(u) - E(q)) - (u - q)) / sqrt(mu),
                                   -2 k (cn(u) - cn(q)) / sqrt(mu)).
With q = K(k) the inflection (cn = 0) is at s = 0: the left side is s in
[-L1, 0], the right side s in [0, L2]; phi of each side is chosen so the
tangents agree at the inflection (theta = phi + 2 asin k there), so the joined
curve is C2 (curvature 0 on both sides).

    >>> kl = keyline_3d(seed=1)
    >>> kl.xyz.shape, kl.inflection_xyz.shape
    ((400, 3), (3,))
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.special import ellipj, ellipk, elliprd, elliprf


def ellip_e(phi, m):
    """Incomplete elliptic integral of the second kind E(phi | m) for any real phi,
    by Carlson's R_F, R_D (DLMF 19.25.9) and E(phi + j pi) = E(phi) + 2 j E(m).
    (Debian 12's scipy 1.10.1 ellipeinc returns wrong values for some arguments,
    e.g. ellipeinc(0.5622068731514482, 0.49) = 0.633 instead of 0.5483.)"""
    phi = np.asarray(phi, dtype=float)
    j = np.round(phi / np.pi)
    p = phi - j * np.pi                               # |p| <= pi/2
    sp, cp = np.sin(p), np.cos(p)
    d = 1.0 - m * sp * sp
    e = sp * elliprf(cp * cp, d, 1.0) - (m / 3.0) * sp ** 3 * elliprd(cp * cp, d, 1.0)
    ecomp = elliprf(0.0, 1.0 - m, 1.0) - (m / 3.0) * elliprd(0.0, 1.0 - m, 1.0)
    return e + 2.0 * j * ecomp


def elastica_points(s, mu: float, k: float, q: float, phi: float = 0.0):
    """Points (n, 2), tangent angle (n,) and curvature (n,) of the smooth elastica
    with gamma(0) = 0 at arc lengths s (k <= 1)."""
    s = np.asarray(s, dtype=float)
    m = k * k
    rm = np.sqrt(mu)
    u = rm * s + q
    sn, cn, dn, am = ellipj(u, m)
    sn0, cn0, dn0, am0 = ellipj(q, m)
    E = ellip_e(am, m)
    E0 = ellip_e(am0, m)
    x = (2.0 * (E - E0) - (u - q)) / rm
    y = -2.0 * k * (cn - cn0) / rm
    c, sphi = np.cos(phi), np.sin(phi)
    pts = np.column_stack([c * x - sphi * y, sphi * x + c * y])
    theta = phi + 2.0 * np.arctan2(k * sn, dn)
    kappa = 2.0 * k * rm * cn
    return pts, theta, kappa


def random_rotation(rng: np.random.Generator) -> np.ndarray:
    """A uniformly random proper rotation (3, 3) (QR of a Gaussian matrix)."""
    q, r = np.linalg.qr(rng.standard_normal((3, 3)))
    q = q * np.sign(np.diag(r))
    if np.linalg.det(q) < 0:
        q[:, 2] = -q[:, 2]
    return q


@dataclass
class Keyline:
    """A generated keyline. ``xyz`` (n, 3) noisy 3D samples in scanner coordinates;
    ``xyz_clean`` the same samples without noise (exactly on the plane);
    ``xy`` (n, 2) their clean coordinates in the design plane (inflection at the
    origin, tangent there along +x); ``s`` (n,) arc length from the left end;
    ``kappa`` (n,) signed curvature; ``plane_origin``, ``plane_u``, ``plane_v``,
    ``plane_normal``: xyz_clean = origin + x u + y v; ``inflection_xyz`` /
    ``inflection_s``: the true inflection; ``inflection_index`` the sample
    nearest it; ``length`` total arc length; ``noise`` the noise sigma (units of
    length); ``left`` / ``right``: elastica parameters (mu, k, q, phi, length) of
    each side, each in design-plane coordinates with gamma(0) at the inflection
    (left side parametrised by s in [-length, 0])."""
    xyz: np.ndarray
    xyz_clean: np.ndarray
    xy: np.ndarray
    s: np.ndarray
    kappa: np.ndarray
    plane_origin: np.ndarray
    plane_u: np.ndarray
    plane_v: np.ndarray
    plane_normal: np.ndarray
    inflection_xyz: np.ndarray
    inflection_s: float
    inflection_index: int
    length: float
    noise: float
    left: dict = field(default_factory=dict)
    right: dict = field(default_factory=dict)


def keyline_2d(n: int = 400, length: float = 300.0, k_left: float = 0.3, k_right: float = 0.38,
               frac_left: float = 0.42, reach_left: float = 1.6, reach_right: float = 1.4,
               irregular: float = 0.3, rng=None):
    """Clean design-plane keyline: (xy (n,2), s (n,), kappa (n,), s_inflection, left, right).

    The left side covers reach_left quarter-periods K/sqrt(mu) of the curvature
    (ending at the inflection; reach in (1, 2) includes the crest, where |kappa|
    is largest, and no second inflection), the right side reach_right; frac_left
    of the length is on the left. The defaults (k about 0.3-0.4, sine-like)
    resemble the pantile keylines of seed 000 Table 1. Samples are at irregular arc lengths (relative jitter
    ``irregular`` of the mean spacing), the first and last at the ends.
    """
    rng = np.random.default_rng(rng)
    L1, L2 = frac_left * length, (1.0 - frac_left) * length
    K1, K2 = ellipk(k_left ** 2), ellipk(k_right ** 2)
    mu1 = (reach_left * K1 / L1) ** 2          # sqrt(mu) L = reach * K
    mu2 = (reach_right * K2 / L2) ** 2
    # tangent at the inflection along +x on both sides: phi + 2 asin(k) = 0
    phi1, phi2 = -2.0 * np.arcsin(k_left), -2.0 * np.arcsin(k_right)
    step = length / (n - 1)
    s = np.arange(n) * step + rng.uniform(-irregular, irregular, n) * step
    s[0], s[-1] = 0.0, length
    s = np.sort(np.clip(s, 0.0, length))
    sl = s - L1                                  # arc length from the inflection
    left_pts, _, kl = elastica_points(sl[sl < 0], mu1, k_left, K1, phi1)
    right_pts, _, kr = elastica_points(sl[sl >= 0], mu2, k_right, K2, phi2)
    xy = np.vstack([left_pts, right_pts])
    kappa = np.concatenate([kl, kr])
    left = dict(mu=mu1, k=k_left, q=K1, phi=phi1, length=L1)
    right = dict(mu=mu2, k=k_right, q=K2, phi=phi2, length=L2)
    return xy, s, kappa, L1, left, right


def keyline_3d(n: int = 400, length: float = 300.0, noise: float = 1e-3, seed: int = 0,
               offset: float = 1000.0, **kw) -> Keyline:
    """A realistic 3D keyline: :func:`keyline_2d` (``**kw``) on a randomly
    tilted plane through a random point within ``offset`` of the origin, with
    isotropic Gaussian noise of sigma ``noise * length``, reproducible from
    ``seed``."""
    rng = np.random.default_rng(seed)
    xy, s, kappa, s_infl, left, right = keyline_2d(n=n, length=length, rng=rng, **kw)
    R = random_rotation(rng)
    u, v, normal = R[:, 0], R[:, 1], R[:, 2]
    origin = rng.uniform(-offset, offset, 3)
    clean = origin + xy[:, :1] * u + xy[:, 1:] * v
    sigma = noise * length
    noisy = clean + rng.normal(0.0, sigma, clean.shape) if sigma > 0 else clean.copy()
    return Keyline(xyz=noisy, xyz_clean=clean, xy=xy, s=s, kappa=kappa, plane_origin=origin,
                   plane_u=u, plane_v=v, plane_normal=normal, inflection_xyz=origin.copy(),
                   inflection_s=float(s_infl), inflection_index=int(np.argmin(np.abs(s - s_infl))),
                   length=float(length), noise=float(sigma), left=left, right=right)
