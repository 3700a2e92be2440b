#!/usr/bin/python3
"""Design checks for the superfluid model's reversible part (paper 3, Kincl, Schmoranzer, Pavelka
2023, eq. 19 with beta = mu = 0), in plain float64 on small 2D/3D particle sets.

1. energy: dE/dt = grad E . f vanishes (checks T = de/ds with its flow part, eq. 15);
2. divergence of the vector field f in several choices of stored variables, by central finite
   differences: an exactly invertible map of integers is a lattice bijection, so it can only
   approximate a flow that preserves volume in the stored variables (design note sec. 4);
3. the analytic split of that divergence (README, "The reversible step") against (2);
4. the paper's time stepper (sec. II.E) and the engine's doubled one (README) against RK4 on a
   small second-sound case, and the doubled scheme's copy difference on a random droplet.

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


# ---- time steppers: the paper's (sec. II.E), the doubled one of the engine (README), RK4 ----

def square_grid(n, L):
    g = (np.arange(n) + 0.5) * L / n
    X, Y = np.meshgrid(g, g, indexing='ij')
    return np.stack([X.ravel(), Y.ravel()], -1)

def second_sound(N, A, L=0.01):
    x = square_grid(N, L)
    dr = L / N
    m = np.full(len(x), RHO0 * dr**2)
    part = Particles.__new__(Particles)
    part.m, part.h, part.dim = m, 3 * dr, 2
    w, _ = kernel(part.distances(x)[1], part.h, 2)
    part.c = RHO0 - w @ m
    s = S0 + A * S0 * np.sin(np.pi * x[:, 0] / L) * np.sin(np.pi * x[:, 1] / L)
    z = np.zeros_like(x)
    return part, [x, z.copy(), z.copy(), s]

def split_rates(part, x, v, u, s):
    """(F_v, Phi_u, Phi_s) in variables (x, v, u = v - v_s, s)."""
    _, vdot, vsdot, sdot = part.rates(x, v, v - u, s)
    return vdot, vdot - vsdot, sdot

def paper_step(part, st, dt, cache):
    x, v, vs, s = st
    if cache.get('r') is None:
        cache['r'] = part.rates(x, v, vs, s)
    _, vd, vsd, _ = cache['r']
    v = v + dt / 2 * vd; vs = vs + dt / 2 * vsd
    x = x + dt / 2 * v
    sd = part.rates(x, v, vs, s)[3]
    s = s + dt * sd            # the paper prints dt/2 (step 5): a slip, s must advance by dt
    x = x + dt / 2 * v
    r = part.rates(x, v, vs, s); cache['r'] = r
    v = v + dt / 2 * r[1]; vs = vs + dt / 2 * r[2]
    return [x, v, vs, s]

def rk4_step(part, st, dt):
    def f(y): return list(part.rates(*y))
    k1 = f(st); y = [a + dt / 2 * b for a, b in zip(st, k1)]
    k2 = f(y); y = [a + dt / 2 * b for a, b in zip(st, k2)]
    k3 = f(y); y = [a + dt * b for a, b in zip(st, k3)]
    k4 = f(y)
    return [a + dt / 6 * (b + 2 * c + 2 * d + e) for a, b, c, d, e in zip(st, k1, k2, k3, k4)]

def full_step(part, st, dt):
    """D(h/2) A(h/2) B(h) A(h/2) D(h/2); copies y_i = (v_i, u_i, s_i); the drift uses the mean v."""
    x, v1, u1, s1, v2, u2, s2 = st
    x = x + dt / 2 * 0.5 * (v1 + v2)
    fv, pu, ps = split_rates(part, x, v2, u2, s2); v1 = v1 + dt / 2 * fv; u1 = u1 + dt / 2 * pu; s1 = s1 + dt / 2 * ps
    fv, pu, ps = split_rates(part, x, v1, u1, s1); v2 = v2 + dt * fv; u2 = u2 + dt * pu; s2 = s2 + dt * ps
    fv, pu, ps = split_rates(part, x, v2, u2, s2); v1 = v1 + dt / 2 * fv; u1 = u1 + dt / 2 * pu; s1 = s1 + dt / 2 * ps
    x = x + dt / 2 * 0.5 * (v1 + v2)
    return [x, v1, u1, s1, v2, u2, s2]

def to_full(st):
    x, v, vs, s = st
    return [x, v, v - vs, s, v.copy(), v - vs, s]

def from_full(d):
    x, v1, u1, s1, v2, u2, s2 = d
    v = 0.5 * (v1 + v2)
    return [x, v, v - 0.5 * (u1 + u2), 0.5 * (s1 + s2)]


def order_check(N, A, t_end):
    part, st0 = second_sound(N, A)
    h = 3 * 0.01 / N

    def run(stepper, M, conv_in=lambda s: s, conv_out=lambda s: s):
        dt = h / (M * U1)
        n = int(round(t_end / dt))
        dt = t_end / n
        st = conv_in([a.copy() for a in st0])
        cache = {}
        for _ in range(n):
            st = stepper(st, dt, cache)
        return conv_out(st), st

    def err(a, b):
        return max(np.abs(a[3] - b[3]).max() / S0, np.abs(a[2] - b[2]).max(), np.abs(a[1] - b[1]).max())

    ref, _ = run(lambda s, dt, c: rk4_step(part, s, dt), 400)
    E0 = part.energy(*st0)
    print(f'second sound, N = {N}, A = {A}, t = {t_end} s: errors against RK4 at M = 400')
    for M in (25, 50, 100):
        p, _ = run(lambda s, dt, c: paper_step(part, s, dt, c), M)
        d, dd = run(lambda s, dt, c: full_step(part, s, dt), M, to_full, from_full)
        print(f'   M = {M:3d}: paper {err(p, ref):.3e}, doubled {err(d, ref):.3e}, paper - doubled '
              f'{err(p, d):.3e}; copies |v_s - v_s\'| {np.abs((dd[1] - dd[2]) - (dd[4] - dd[5])).max():.2e} m/s;'
              f' dE/E paper {part.energy(*p) / E0 - 1:.2e}, doubled {part.energy(*d) / E0 - 1:.2e}')


def droplet_check(steps):
    part, st = random_droplet(9, 2, 1, speed=0.3, counterflow=0.3, ds=0.01)
    dt = part.h / (10 * U1)
    E0 = part.energy(*st)
    d = to_full(st)
    print(f'random droplet, {len(st[0])} particles, doubled scheme, dt = {dt:.3e} s:')
    for i in range(1, steps + 1):
        d = full_step(part, d, dt)
        if i % (steps // 4) == 0:
            du = max(np.abs(d[1] - d[4]).max(), np.abs(d[2] - d[5]).max())
            print(f'   step {i}: max copy difference in v, v - v_s {du:.2e} m/s, in s / s0 '
                  f'{np.abs(d[3] - d[6]).max() / S0:.2e}; dE/E {part.energy(*from_full(d)) / E0 - 1:.2e}')


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
    order_check(12, 0.1, 1e-4)
    order_check(12, 0.01, 1e-4)
    droplet_check(4000)


if __name__ == '__main__':
    main()
