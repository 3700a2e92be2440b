#!/usr/bin/python3
"""Design checks for the superfluid model's reversible part (paper 3, Kincl, Schmoranzer, Pavelka
2023, eq. 19 with beta = mu = 0), in plain float64 on small 2D/3D particle sets.

1. energy: dE/dt = grad E . f vanishes (checks T = de/ds with its flow part, eq. 15);
2. divergence of the vector field f in several choices of stored variables, by central finite
   differences: an exactly invertible map of integers is a lattice bijection, so it can only
   approximate a flow that preserves volume in the stored variables (design note sec. 4);
3. the analytic split of that divergence (README, "Why the state is doubled") against (2).

Run: /usr/bin/python3 models/superfluid/scheme_check.py
"""
import numpy as np

# Table I, second sound (T0 = 1.9 K), SI units
RHO0, S0, CHI_N0, CHI_P, U1, C, T0 = 145.5, 725.5, 0.4195, 5.697e-4, 40.0, 3902.0, 1.9


def kernel(r, h, dim):
    """Wendland (17): w and w'/r."""
    q = 7.0 / (4.0 * np.pi) if dim == 2 else 21.0 / (16.0 * np.pi)
    x = np.clip(1.0 - r / (2.0 * h), 0.0, None)
    w = q / h**dim * x**4 * (1.0 + 2.0 * r / h)
    w_over_r = -5.0 * q / h ** (dim + 2) * x**3
    return w, w_over_r


class Particles:
    def __init__(self, x, m, h, dim):
        self.m, self.h, self.dim = m, h, dim
        w, _ = kernel(self.distances(x)[1], h, dim)
        self.c = RHO0 * (1.0 + 0.01 * np.random.default_rng(7).standard_normal(len(x))) - w @ m

    def distances(self, x):
        rab = x[:, None, :] - x[None, :, :]
        return rab, np.sqrt((rab**2).sum(-1))

    def fields(self, x, v, vs, s):
        rab, r = self.distances(x)
        w, wr = kernel(r, self.h, self.dim)
        np.fill_diagonal(wr, 0.0)
        rho = w @ self.m + self.c  # eq. (24)
        chin = CHI_N0 + CHI_P * (s - S0)  # eq. (8)
        chis = 1.0 - chin
        vns = (v - vs) / chin[:, None]  # eq. (22)
        vn = (v - chis[:, None] * vs) / chin[:, None]
        T = T0 * (1.0 + (s - S0) / C) - 0.5 * CHI_P * (vns**2).sum(-1)  # de/ds of eq. (15)
        p = U1**2 * (rho - RHO0)  # eq. (12)
        return rab, wr, rho, chin, chis, vns, vn, T, p

    def rates(self, x, v, vs, s):
        """Eq. (19), reversible part."""
        rab, wr, rho, chin, chis, vns, vn, T, p = self.fields(x, v, vs, s)
        g = self.m[None, :] * wr  # m_b w'_ab / r_ab
        j = (rho * s * chis)[:, None] * vns  # eq. (21)
        jr = j / rho[:, None] ** 2
        sdot = -np.einsum('ab,abk,ak->a', g, rab, jr) - np.einsum('ab,abk,bk->a', g, rab, jr)
        Pi = (rho * chin * chis)[:, None, None] * vns[:, :, None] * vns[:, None, :]
        Pi += p[:, None, None] * np.eye(self.dim)
        Pr = Pi / rho[:, None, None] ** 2
        vdot = -np.einsum('ab,aij,abj->ai', g, Pr, rab) - np.einsum('ab,bij,abj->ai', g, Pr, rab)
        vnab = vn[:, None, :] - vn[None, :, :]
        coef = (chin / rho)[:, None] * np.einsum('abk,ak->ab', vnab, vns)
        pr = p / rho**2
        coef2 = pr[:, None] + pr[None, :] + (s / rho)[:, None] * (T[:, None] - T[None, :])
        vsdot = -np.einsum('ab,abk->ak', g * (coef + coef2), rab)
        return v.copy(), vdot, vsdot, sdot

    def energy(self, x, v, vs, s):
        rab, wr, rho, chin, chis, vns, vn, T, p = self.fields(x, v, vs, s)
        ds = s - S0
        e = 0.5 * (v**2).sum(-1) + 0.5 * chis / chin * ((v - vs) ** 2).sum(-1)
        e += U1**2 * (np.log(rho / RHO0) + RHO0 / rho - 1.0) + T0 * ds + T0 / (2 * C) * ds**2
        return (self.m * e).sum()


def random_droplet(n_side, dim, seed, speed, counterflow, ds):
    rng = np.random.default_rng(seed)
    dr = 1.0e-3
    grid = np.stack(np.meshgrid(*[np.arange(n_side) * dr] * dim, indexing='ij'), -1)
    x = grid.reshape(-1, dim)
    x = x[((x - x.mean(0)) ** 2).sum(-1) <= (0.5 * n_side * dr) ** 2]
    x = x + 0.05 * dr * rng.standard_normal(x.shape)
    n = len(x)
    m = np.full(n, RHO0 * dr**dim)
    part = Particles(x, m, 1.5 * dr, dim)
    v = speed * rng.standard_normal((n, dim))
    vs = v - counterflow * rng.standard_normal((n, dim))
    s = S0 * (1.0 + ds * rng.standard_normal(n))
    return part, [x, v, vs, s]


def pack(state):
    return np.concatenate([a.ravel() for a in state])


def unpack(y, like):
    out, i = [], 0
    for a in like:
        out.append(y[i:i + a.size].reshape(a.shape))
        i += a.size
    return out


def divergence(part, state, transform=None, eps=1e-7):
    """Divergence of f in the stored variables Y = transform(y): div_Y f = div_y f + d/dt log det dY/dy."""
    f = lambda y: pack(part.rates(*unpack(y, state)))
    y0 = pack(state)
    div = 0.0
    scale = np.abs(y0) + 1.0
    for i in range(y0.size):
        d = eps * scale[i]
        yp, ym = y0.copy(), y0.copy()
        yp[i] += d
        ym[i] -= d
        div += (f(yp)[i] - f(ym)[i]) / (2 * d)
    if transform is not None:
        rate = f(y0)
        dt = 1e-9
        div += (transform(unpack(y0 + dt * rate, state)) - transform(unpack(y0 - dt * rate, state))) / (2 * dt)
    return div


def main():
    for dim, n_side in ((2, 9), (3, 5)):
        part, state = random_droplet(n_side, dim, 1, speed=0.3, counterflow=0.3, ds=0.05)
        rates = part.rates(*state)
        grad = []
        y0 = pack(state)
        for i in range(y0.size):
            d = 1e-6 * (abs(y0[i]) + 1e-3)
            yp, ym = y0.copy(), y0.copy()
            yp[i] += d
            ym[i] -= d
            grad.append((part.energy(*unpack(yp, state)) - part.energy(*unpack(ym, state))) / (2 * d))
        dEdt = np.dot(grad, pack(rates))
        power = np.abs(np.array(grad) * pack(rates)).sum()
        print(f'{dim}D, {len(state[0])} particles: dE/dt = {dEdt:.3e} against sum |terms| {power:.3e}')
        div = divergence(part, state)
        # log det of the change to Y: entropy stored as s / rho (scalar per particle)
        logrho = lambda st: -np.log(part.fields(*st)[2]).sum()
        div_y = divergence(part, state, logrho)
        rate_scale = np.abs(pack(rates)[state[0].size:]).mean() / np.abs(y0[state[0].size:]).mean()
        x, v, vs, s = state
        rab, wr, rho, chin, chis, vns, vn, T, p = part.fields(*state)
        g = part.m[None, :] * wr
        G = np.einsum('ab,abk->ak', g, rab)  # grad_a of the kernel sum
        Ghat = part.m[:, None] * np.einsum('ab,abk->ak', wr / rho[None, :], rab)
        ku = (chis / chin)[:, None] * (v - vs)
        rhodot = np.einsum('ab,abk,abk->a', g, rab, v[:, None, :] - v[None, :, :])
        bulk = (rhodot / rho).sum()
        rest = (ku * (Ghat - dim * G / rho[:, None])).sum()
        print(f'   analytic: sum rhodot/rho = {bulk:.4e}, sum k u.(Ghat - d G/rho) = {rest:.4e},'
              f' total {bulk + rest:.4e} 1/s')
        print(f'   div f in (x, v, v_s, s) = {div:.4e} 1/s; with s / rho stored: {div_y:.4e} 1/s;'
              f' typical rate {rate_scale:.3e} 1/s')


if __name__ == '__main__':
    main()
