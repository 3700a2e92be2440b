"""The lid-driven cavity against Ghia, Ghia & Shin (1982), shared by the models' cavity figures
(superfluid_cavity.py, two_fluid_cavity.py): the reference profiles, the centre-line velocities of
a particle state (Shepard averages, core's Wendland C2 kernel) and their L-infinity errors."""

import numpy as np

from revsph_runs import REPO, read_csv
from shtc_fluids import shepard

REFDATA = REPO.parent / "shared" / "refdata"


def ghia(re):
    u = read_csv(REFDATA / "ghia1982_u_vertical_centerline.csv")
    v = read_csv(REFDATA / "ghia1982_v_horizontal_centerline.csv")
    return u["y"], u[f"Re{re}"], v["x"], v[f"Re{re}"]


class CentreLines:
    """u on x = 1/2 and v on y = 1/2 of a state (positions, velocities of fluid and walls), and
    the largest distance from Ghia's points at Reynolds number `re`: everywhere (`error`) and
    at Ghia's points at least one support inside the cavity (`interior`)."""

    def __init__(self, position, velocity, support, re):
        self.position, self.velocity, self.support = position, velocity, support
        y_ref, u_ref, x_ref, v_ref = ghia(re)
        u_error = np.abs(self.u_at(y_ref) - u_ref)
        v_error = np.abs(self.v_at(x_ref) - v_ref)
        u_inside = (y_ref >= support) & (y_ref <= 1.0 - support)
        v_inside = (x_ref >= support) & (x_ref <= 1.0 - support)
        self.error = max(u_error.max(), v_error.max())
        self.interior = max(u_error[u_inside].max(), v_error[v_inside].max())

    def u_at(self, y):
        points = np.column_stack([np.full_like(y, 0.5), y])
        return shepard(points, self.position, self.velocity, self.support)[:, 0]

    def v_at(self, x):
        points = np.column_stack([x, np.full_like(x, 0.5)])
        return shepard(points, self.position, self.velocity, self.support)[:, 1]


def draw_ghia(u_axis, v_axis, re):
    """Ghia's points on a u(y) and a v(x) axis, labelled and with legends."""
    y_ref, u_ref, x_ref, v_ref = ghia(re)
    u_axis.plot(u_ref, y_ref, "ko", ms=3, mfc="none", label="Ghia et al. (1982)")
    v_axis.plot(x_ref, v_ref, "ko", ms=3, mfc="none", label="Ghia et al. (1982)")
    u_axis.set(xlabel="u on x = 1/2", ylabel="y", title=f"Re = {re}")
    v_axis.set(xlabel="x", ylabel="v on y = 1/2", title=f"Re = {re}")
    u_axis.legend(fontsize=7)
    v_axis.legend(fontsize=7)
