"""Statics of chapter 14's leaning staircase on the solver's contact springs.

/usr/bin/python3 benchmarks/staircase_model.py

Twenty boxes of 0.6 x 0.5 x 0.6 m (500 kg/m^3), box k placed `lean` k
further along x than the one below; by rigid statics they tip when lean >
0.030 m. The soft step (common/domains/src/physics_solver.cpp) gives each of
a contact's four points a spring of stiffness m_eff * omega^2, m_eff the
point's effective mass (1 / the velocity a unit impulse makes there, turning
included) and omega = 2 pi 120 Hz; at rest a contact therefore resists a
tilt like a rotational spring of 4 k (w/2)^2, w the width the two boxes
overlap. This model solves the small-tilt equilibrium of the twenty boxes on
those springs (rigid boxes, the load of all boxes above each contact taken
about the centre of that contact) and prints, for each lean and each
multiple of the springs' stiffness, how far the load above the worst
contact sits out of its centre (100% = over the edge: the near points carry
nothing and the stack tips) and how far the top box has moved out.
"""

import numpy as np

BOXES = 20
HALF = np.array([0.3, 0.25, 0.3])
MASS = 500.0 * 8.0 * HALF.prod()
GRAVITY = 9.81
OMEGA = 2.0 * np.pi * 120.0


def point_effective_mass(moving_bodies):
    """1 / (sum over the moving bodies of 1/m + (r x n) . I^-1 (r x n)) at a
    corner of the contact face, n the vertical."""
    inertia = MASS / 3.0 * np.array(
        [HALF[1] ** 2 + HALF[2] ** 2, HALF[0] ** 2 + HALF[2] ** 2, HALF[0] ** 2 + HALF[1] ** 2]
    )
    r = np.array([HALF[0], HALF[1], HALF[2]])
    r_cross_n = np.cross(r, [0.0, 1.0, 0.0])
    per_body = 1.0 / MASS + np.sum(r_cross_n**2 / inertia)
    return 1.0 / (moving_bodies * per_body)


def equilibrium(lean, stiffer):
    # Contact 0 is the floor's (one moving body), contact j > 0 is between
    # box j - 1 and box j; the overlap is 0.6 - lean wide there.
    half_width = [HALF[0]] + [HALF[0] - lean / 2.0] * (BOXES - 1)
    centre = [0.0] + [lean * (j - 0.5) for j in range(1, BOXES)]
    stiffness = [
        stiffer * 4.0 * point_effective_mass(1 if j == 0 else 2) * OMEGA**2 * half_width[j] ** 2
        for j in range(BOXES)
    ]
    # Unknowns: each box's tilt phi_i (small). Box i's centre moves out by
    # the tilts below it times their heights: sum_{k<i} 0.5 phi_k + 0.25 phi_i.
    weight = MASS * GRAVITY
    height = 2.0 * HALF[1]
    a = np.zeros((BOXES, BOXES))
    b = np.zeros(BOXES)
    for j in range(BOXES):
        a[j, j] += stiffness[j]
        if j > 0:
            a[j, j - 1] -= stiffness[j]
        for i in range(j, BOXES):
            b[j] += weight * (lean * i - centre[j])
            a[j, :i] -= weight * height
            a[j, i] -= weight * height / 2.0
    phi = np.linalg.solve(a, b)
    moved = [phi[:i].sum() * height + phi[i] * height / 2.0 for i in range(BOXES)]
    worst = max(
        (np.mean([lean * i + moved[i] for i in range(j, BOXES)]) - centre[j]) / half_width[j]
        for j in range(BOXES)
    )
    return worst, moved[-1]


def main():
    print(
        f"point effective mass: {point_effective_mass(2):.2f} kg between two boxes, "
        f"{point_effective_mass(1):.2f} kg on the floor"
    )
    for share in (0.3, 0.63, 0.8, 0.93):
        for stiffer in (1, 2, 4, 8, 16):
            worst, top = equilibrium(share * 0.030, stiffer)
            print(
                f"lean {share:.0%} of tipping, springs x{stiffer:<2}: load centre at "
                f"{worst:.0%} of the half-width, top {top * 1000:.0f} mm out"
            )


if __name__ == "__main__":
    main()
