"""The plane-sections solution of a plane-strain strip bent by its outer fibre's nominal strain: each fibre in
plane-strain uniaxial stress (sigma_yy = 0) at its log strain ln(1 + kappa y), J2 with linear kinematic (Prager,
modulus c) and isotropic (slope h) hardening integrated by a radial return (exact per substep for linear
hardening), the moment summed over the fibres on the current thickness (the fibres' thickness stretch).
Shared by tests/check_bending.py and tests/check_springback_bending.py; no part of it comes from the solver."""
import numpy as np


class Strip:
    def __init__(self, e, nu, sy0):
        self.sy0 = sy0
        self.g = e / (2 * (1 + nu))
        lam = e * nu / ((1 + nu) * (1 - 2 * nu))
        self.d = np.array([[lam + 2 * self.g, lam, lam], [lam, lam + 2 * self.g, lam], [lam, lam, lam + 2 * self.g]])

    def fibre_update(self, state, dxx, dyy, c, h):
        """Backward-Euler radial return of every fibre (Kirchhoff term -sigma tr(de) as in tests/check_kinematic.py)."""
        s, a, p = state
        de = np.stack([dxx, dyy, np.zeros_like(dxx)], 1)
        trial = s + de @ self.d.T - s * (dxx + dyy)[:, None]
        mean = trial.mean(1, keepdims=True)
        xi = trial - mean - a
        q = np.sqrt(1.5 * (xi * xi).sum(1))
        dp = np.where(q > self.sy0 + h * p, (q - self.sy0 - h * p) / (3 * self.g + c + h), 0.0)
        n = xi / np.maximum(q, 1e-300)[:, None]
        return trial - 3 * self.g * dp[:, None] * n, a + c * dp[:, None] * n, p + dp

    def fibre_syy(self, state, dxx, dyy, c, h):
        """sigma_yy of fibre_update's result alone, component by component (the secant steps need no more)."""
        s, a, p = state
        d, tr = self.d, dxx + dyy
        t = [s[:, i] + (dxx * d[i, 0] + dyy * d[i, 1]) - s[:, i] * tr for i in range(3)]
        mean = (t[0] + t[1] + t[2]) / 3
        xi = [t[i] - mean - a[:, i] for i in range(3)]
        q = np.sqrt(1.5 * (xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]))
        dp = np.where(q > self.sy0 + h * p, (q - self.sy0 - h * p) / (3 * self.g + c + h), 0.0)
        return t[1] - 3 * self.g * dp * (xi[1] / np.maximum(q, 1e-300))

    def moments(self, strokes, c, h, sub=4, nf=4000, y_fibres=()):
        """The moment at the outer-fibre strains `strokes` (c: Prager modulus, h: isotropic slope, MPa), `sub`
        substeps between them, `nf` fibres; with `y_fibres` (initial y of fibres of a 1 mm strip), also their
        states (sigma, backstress, p) at each stroke."""
        y0 = np.concatenate([(np.arange(nf) + 0.5) / nf - 0.5, np.asarray(y_fibres, float)])
        n = len(y0)
        state, eyy, moments, kept = (np.zeros((n, 3)), np.zeros((n, 3)), np.zeros(n)), np.zeros(n), [0.0], [None]
        for a, b in zip(strokes[:-1], strokes[1:]):
            for e0, e1 in zip(np.linspace(a, b, sub + 1)[:-1], np.linspace(a, b, sub + 1)[1:]):
                dxx = np.log1p(2 * e1 * y0) - np.log1p(2 * e0 * y0)
                ya, yb = -0.5 * dxx, -0.4 * dxx  # secant on d_yy for sigma_yy = 0, fibre by fibre
                fa, fb = self.fibre_syy(state, dxx, ya, c, h), self.fibre_syy(state, dxx, yb, c, h)
                for _ in range(40):
                    move = (np.abs(fb) > 1e-11) & (fb != fa)
                    if not move.any():
                        break
                    ya, fa, yb = yb, fb, np.where(move, yb - fb * (yb - ya) / np.where(move, fb - fa, 1), yb)
                    fb = self.fibre_syy(state, dxx, yb, c, h)
                state, eyy = self.fibre_update(state, dxx, yb, c, h), eyy + yb
            # the current thickness: each fibre's share stretched by exp(e_yy), lever arms from the middle
            dy = np.exp(eyy[:nf]) / nf
            half = nf // 2
            y = np.concatenate([-(np.cumsum(dy[:half][::-1]) - 0.5 * dy[:half][::-1])[::-1],
                                np.cumsum(dy[half:]) - 0.5 * dy[half:]])
            moments.append(float((state[0][:nf, 0] * y * dy).sum()))
            kept.append(tuple(x[nf:].copy() for x in state))
        return (np.array(moments), kept) if len(y_fibres) else np.array(moments)
