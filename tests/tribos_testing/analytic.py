"""Analytic references shared by the tests and the benchmarks: Hertz
contact, the paper's J2 law (36) in homogeneous uniaxial compression
(1D return map in logarithmic strain), the compressible neo-Hookean body
in uniaxial stretch, and the cylinder's polygonal section. Standard
library only."""

import math


def hertz(P, radius, e_star, dim):
    """Hertz's contact half-width (2D, force per length) or radius (3D)
    and peak pressure for the load P: 2D a = sqrt(4 P R / (pi E*)),
    p0 = 2 P / (pi a); 3D a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi
    a^2)."""
    if dim == 2:
        a = math.sqrt(4 * P * radius / (math.pi * e_star))
        return a, 2 * P / (math.pi * a)
    a = (3 * P * radius / (4 * e_star)) ** (1.0 / 3.0)
    return a, 3 * P / (2 * math.pi * a * a)


# The paper's J2 law (36): E, sigma_0, sigma_inf, delta, H (mm, GPa).
PAPER_J2 = dict(E=206.9, s0=0.45, sinf=0.715, delta=16.93, H=0.12924)


def yield_stress(alpha, law=PAPER_J2):
    """The hardening law (36): s0 + (sinf - s0)(1 - exp(-delta a)) + H a."""
    return (law["s0"] + (law["sinf"] - law["s0"]) *
            (1 - math.exp(-law["delta"] * alpha)) + law["H"] * alpha)


class J2Uniaxial:
    """The J2 law in homogeneous uniaxial stress, integrated by backward
    Euler in logarithmic strain: call update(stretch) along the loading
    path; it returns the Kirchhoff stress and records the phase."""

    def __init__(self, law=PAPER_J2):
        self.law, self.eps_p, self.alpha = law, 0.0, 0.0
        self.phase = "elastic"

    def update(self, stretch):
        law = self.law
        eps = math.log(stretch)
        trial = law["E"] * (eps - self.eps_p)
        self.phase = "elastic"
        if abs(trial) > yield_stress(self.alpha, law):
            da = 0.0
            for _ in range(60):
                a = self.alpha + da
                slope = (law["E"] + (law["sinf"] - law["s0"]) * law["delta"] *
                         math.exp(-law["delta"] * a) + law["H"])
                da += (abs(trial) - law["E"] * da - yield_stress(a, law)) / slope
            self.eps_p += math.copysign(da, trial)
            self.alpha += da
            self.phase = "plastic, " + ("tension" if trial > 0 else
                                        "compression")
        return law["E"] * (eps - self.eps_p)


def j2_forces(stretches, area, law=PAPER_J2):
    """Nominal forces (Kirchhoff stress / stretch x area) of homogeneous
    compression through the sequence of stretches."""
    material = J2Uniaxial(law)
    return [material.update(s) / s * area for s in stretches]


def cylinder_force(k, area, radius=6.35, step=0.2):
    """Plate force on a cylinder section of `area` after k steps of `step`
    mm of parameters/cylinder_compression.prm (half height = radius):
    homogeneous compression with the paper's J2 law."""
    stretches = [(radius - step * j) / radius for j in range(1, k + 1)]
    return abs(j2_forces(stretches, area)[-1]) if k > 0 else 0.0


def polygon_section(radius, chords):
    """Area of the quarter of a circle of `radius` meshed with `chords`
    straight chords (the 3D cylinder's section)."""
    return chords / 2 * radius * radius * math.sin(math.pi / (2 * chords))


def neo_hookean_stress(stretch, E, nu, n_lateral):
    """P_11 of the compressible neo-Hookean W = mu/2 (tr C - 3) - mu ln J
    + lam/2 (ln J)^2 in uniaxial stress, with the lateral stretch s of its
    n_lateral free directions from P_22 = 0 (2D plane strain: 1; 3D: 2)."""
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    s = 1.0
    for _ in range(100):
        J = stretch * s ** n_lateral
        f = mu * (s - 1 / s) + lam * math.log(J) / s
        df = mu * (1 + 1 / s ** 2) + lam * (n_lateral - math.log(J)) / s ** 2
        s -= f / df
    J = stretch * s ** n_lateral
    return mu * (stretch - 1 / stretch) + lam * math.log(J) / stretch


def hertz_impact(mass, velocity, radius, e_star):
    """Hertz's impact of a sphere on a half-space (Johnson, Contact
    Mechanics, 11.4): the largest approach delta = (15 m v^2 / (16 E*
    R^1/2))^(2/5), the peak force 4/3 E* R^1/2 delta^3/2 and the contact
    time 2 delta / v int_0^1 (1 - x^5/2)^(-1/2) dx = 2.9432 delta / v (the
    integral is 2/5 B(2/5, 1/2)). Returns (delta, peak force, time)."""
    delta = (15 * mass * velocity ** 2 /
             (16 * e_star * math.sqrt(radius))) ** 0.4
    force = 4.0 / 3.0 * e_star * math.sqrt(radius) * delta ** 1.5
    integral = 0.4 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)
    return delta, force, 2 * integral * delta / velocity


def signorini_bar(length, wave_speed, velocity, density, area):
    """An elastic bar hitting a rigid wall at `velocity` (1D waves): the
    contact lasts 2 L / c with the force rho c v A, and the bar leaves with
    the velocity reversed. Returns (duration, force)."""
    return 2 * length / wave_speed, density * wave_speed * velocity * area
