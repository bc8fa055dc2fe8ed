"""A reduced finite-element model for unfurl, from the stiffness and mass matrices an FE tool assembles.

Writes MBDyn's modal data file layout (the .fem file unfurl's `flexible: {fem: ...}`
reads; docs/FLEXIBLE.md): the model reduced by Craig and Bampton's component
modes with the node where the body's frame attaches held (its inboard hinge),
the interface nodes (where children, latches and sensors attach) carried by
their static constraint modes, and a few fixed-interface normal modes.

The example is a 3 m boom (a thin-walled carbon-fibre tube, Euler-Bernoulli
elements with consistent masses assembled here, independently of unfurl's own
beam), held at its root and with its tip as the interface. To convert a model
of your own, replace `boom_matrices` with your tool's K and M (for example read
from MatrixMarket files exported by Code_Aster or NASTRAN's OUTPUT4), with six
degrees of freedom per node (u_x, u_y, u_z, theta_x, theta_y, theta_z) in the
body frame, and give the held and interface nodes.

    /usr/bin/python3 examples/fem/boom_fem.py [OUT.fem]
"""
import sys

import numpy as np

from modal_file import craig_bampton, generalized_eigen, write_fem

# The boom: a 3 m CFRP tube, 40 mm across with a 1 mm wall (E 70 GPa along
# the fibres, G 5 GPa, density 1600 kg/m^3, as a quasi-isotropic layup's).
LENGTH = 3.0
ELEMENTS = 16
E, G, RHO = 70e9, 5e9, 1600.0
OUTER, WALL = 0.040, 0.001
INNER = OUTER - 2 * WALL
AREA = np.pi / 4 * (OUTER**2 - INNER**2)
I_BENDING = np.pi / 64 * (OUTER**4 - INNER**4)
J_POLAR = 2 * I_BENDING
NORMAL_MODES = 4


def element_matrices(h):
    """A 3D Euler-Bernoulli element of length h along x: stiffness and consistent mass (12 x 12)."""
    k = np.zeros((12, 12))
    m = np.zeros((12, 12))

    def add(matrix, dofs, block):
        matrix[np.ix_(dofs, dofs)] += block

    bar = np.array([[1.0, -1.0], [-1.0, 1.0]])
    bar_mass = np.array([[2.0, 1.0], [1.0, 2.0]]) / 6
    add(k, [0, 6], E * AREA / h * bar)
    add(m, [0, 6], RHO * AREA * h * bar_mass)
    add(k, [3, 9], G * J_POLAR / h * bar)
    add(m, [3, 9], RHO * J_POLAR * h * bar_mass)
    # Bending in the xy-plane (v, theta_z = v') and in the xz-plane (w,
    # theta_y = -w'): the same cubic Hermite element, the slope's sign flipped.
    for s, dofs in ((1.0, [1, 5, 7, 11]), (-1.0, [2, 4, 8, 10])):
        kb = E * I_BENDING / h**3 * np.array([[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                                                [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]])
        mb = RHO * AREA * h / 420 * np.array([[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
                                                [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]])
        flip = np.diag([1.0, s, 1.0, s])
        add(k, dofs, flip @ kb @ flip)
        add(m, dofs, flip @ mb @ flip)
    return k, m


def boom_matrices():
    """The assembled K and M (6 per node), the nodes' coordinates (3 x n) and their lumped masses (6 x n)."""
    nodes = ELEMENTS + 1
    h = LENGTH / ELEMENTS
    K = np.zeros((6 * nodes, 6 * nodes))
    M = np.zeros_like(K)
    ke, me = element_matrices(h)
    for e in range(ELEMENTS):
        dofs = list(range(6 * e, 6 * e + 12))
        K[np.ix_(dofs, dofs)] += ke
        M[np.ix_(dofs, dofs)] += me
    points = np.zeros((3, nodes))
    points[0] = np.linspace(0, LENGTH, nodes)
    # Each node lumps its half of the neighbouring elements: the mass, and
    # the twist's inertia about the tube's axis.
    share = np.full(nodes, h)
    share[[0, -1]] = h / 2
    lumped = np.zeros((6, nodes))
    lumped[0:3] = RHO * AREA * share
    lumped[3] = RHO * J_POLAR * share
    return K, M, points, lumped


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "examples/fem/boom.fem"
    K, M, points, lumped = boom_matrices()
    tip = ELEMENTS
    T = craig_bampton(K, M, held=list(range(6)), interface=list(range(6 * tip, 6 * tip + 6)),
                      normal_modes=NORMAL_MODES)
    Mr, Kr = T.T @ M @ T, T.T @ K @ T
    write_fem(out, "a 3 m CFRP boom, Craig-Bampton: root held, tip interface (examples/fem/boom_fem.py)", points, T, Mr,
              Kr, lumped, NORMAL_MODES)
    lam, _ = generalized_eigen(Kr, Mr)
    print(out, f"{points.shape[1]} nodes, {T.shape[1]} coordinates,",
          "frequencies (Hz):", " ".join(f"{np.sqrt(x) / (2 * np.pi):.4g}" for x in lam))
    # The cantilever's first bending frequency, beta_1 L = 1.8751.
    f1 = 1.8751**2 / (2 * np.pi * LENGTH**2) * np.sqrt(E * I_BENDING / (RHO * AREA))
    print(f"closed form, first bending: {f1:.4g} Hz")


if __name__ == "__main__":
    main()
