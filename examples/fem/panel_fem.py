"""A reduced finite-element model of a solar-array panel for unfurl: a plate, held along its hinge line.

The panel is zfold_plates' honeycomb panel (0.9 m x 1.2 m, bending stiffness
D = 7435 N m, 3.70 kg/m^2 with its cells; assets/scenes/zfold_plates.yaml
gives the sandwich's source), meshed here with Adini-Clough-Melosh
rectangles (the 12-term polynomial element: w and its two slopes at each
corner, consistent masses for the modal matrices; the lumped masses give
the body's inertia), a different element from unfurl's own plate
(Bogner-Fox-Schmit). The body frame is the hinge's: the root edge (y = 0,
x from -0.45 to 0.45) is held, as a hinge line fastened along its whole
length holds it; the outer edge's corners and middle are the interface
nodes where a tip fitting, a latch or a sensor attaches. The panel is rigid in its own
plane (in-plane stretching is stiffer than bending by (size/thickness)^2),
so each node's in-plane motions are held.

Writes MBDyn's modal data file (modal_file.py): 6 fixed-interface normal modes
and the interface nodes' constraint modes (w and the two slopes).

    /usr/bin/python3 examples/fem/panel_fem.py [OUT.fem]
"""
import sys

import numpy as np

from modal_file import craig_bampton, generalized_eigen, write_fem

WIDTH, SPAN = 0.9, 1.2  # along x (the hinge line), along y (away from it)
ELEMENTS_X, ELEMENTS_Y = 6, 8
D, POISSON, MASS_PER_AREA = 7435.0, 0.33, 3.7037037037037037
NORMAL_MODES = 6
W, THETA_X, THETA_Y = 2, 3, 4  # a node's bending dofs among its six
IN_PLANE = (0, 1, 5)


def monomials(x, y):
    """The element's 12 terms and their derivatives: rows value, d/dx, d/dy, d2/dx2, d2/dy2, d2/dxdy."""
    powers = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2), (3, 0), (2, 1), (1, 2), (0, 3), (3, 1), (1, 3)]

    def term(i, j, dx, dy):
        if dx > i or dy > j:
            return 0.0
        c = np.prod(range(i - dx + 1, i + 1)) * np.prod(range(j - dy + 1, j + 1))
        return c * x ** (i - dx) * y ** (j - dy)

    return np.array([[term(i, j, dx, dy) for (i, j) in powers]
                     for dx, dy in ((0, 0), (1, 0), (0, 1), (2, 0), (0, 2), (1, 1))])


def element_matrices(a, b):
    """The ACM rectangle (a x b): stiffness and consistent mass (12 x 12), dofs (w, theta_x, theta_y) per corner."""
    corners = [(0.0, 0.0), (a, 0.0), (a, b), (0.0, b)]
    C = np.vstack([np.array([m[0], m[2], -m[1]]) for m in (monomials(x, y) for x, y in corners)])
    Cinv = np.linalg.inv(C)
    bending = D * np.array([[1.0, POISSON, 0.0], [POISSON, 1.0, 0.0], [0.0, 0.0, (1 - POISSON) / 2]])
    g, wg = np.polynomial.legendre.leggauss(4)  # exact for the mass's degree-6 products
    k = np.zeros((12, 12))
    m = np.zeros((12, 12))
    for gx, wx in zip(g, wg):
        for gy, wy in zip(g, wg):
            x, y = a * (gx + 1) / 2, b * (gy + 1) / 2
            P = monomials(x, y)
            N = P[0] @ Cinv
            B = np.vstack([P[3], P[4], 2 * P[5]]) @ Cinv  # curvatures w_xx, w_yy, 2 w_xy
            weight = wx * wy * a * b / 4
            k += weight * B.T @ bending @ B
            m += weight * MASS_PER_AREA * np.outer(N, N)
    return k, m


def panel_matrices():
    """The assembled K and M (6 per node), the nodes' coordinates (3 x n) and their lumped masses (6 x n)."""
    nx, ny = ELEMENTS_X + 1, ELEMENTS_Y + 1
    a, b = WIDTH / ELEMENTS_X, SPAN / ELEMENTS_Y
    node = lambda i, j: j * nx + i  # noqa: E731
    K = np.zeros((6 * nx * ny, 6 * nx * ny))
    M = np.zeros_like(K)
    ke, me = element_matrices(a, b)
    for j in range(ELEMENTS_Y):
        for i in range(ELEMENTS_X):
            corners = [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
            dofs = [6 * c + d for c in corners for d in (W, THETA_X, THETA_Y)]
            K[np.ix_(dofs, dofs)] += ke
            M[np.ix_(dofs, dofs)] += me
    points = np.zeros((3, nx * ny))
    lumped = np.zeros((6, nx * ny))
    for j in range(ny):
        for i in range(nx):
            points[0:2, node(i, j)] = (-WIDTH / 2 + i * a, j * b)
            # Each node lumps its share of the four elements around it.
            share = (a if 0 < i < nx - 1 else a / 2) * (b if 0 < j < ny - 1 else b / 2)
            lumped[0:3, node(i, j)] = MASS_PER_AREA * share
    return K, M, points, lumped, node


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "examples/fem/panel.fem"
    K, M, points, lumped, node = panel_matrices()
    nodes = points.shape[1]
    root = [node(i, 0) for i in range(ELEMENTS_X + 1)]
    tip = [node(0, ELEMENTS_Y), node(ELEMENTS_X // 2, ELEMENTS_Y), node(ELEMENTS_X, ELEMENTS_Y)]
    held = [6 * n + d for n in root for d in (W, THETA_X, THETA_Y)] + [6 * n + d for n in range(nodes) for d in IN_PLANE]
    interface = [6 * n + d for n in tip for d in (W, THETA_X, THETA_Y)]
    T = craig_bampton(K, M, held=held, interface=interface, normal_modes=NORMAL_MODES)
    Mr, Kr = T.T @ M @ T, T.T @ K @ T
    write_fem(out, "a 0.9 m x 1.2 m honeycomb panel, ACM plate, Craig-Bampton: root edge held, outer edge's corners "
              "and middle the interface (examples/fem/panel_fem.py)", points, T, Mr, Kr, lumped, NORMAL_MODES)
    lam, _ = generalized_eigen(Kr, Mr)
    print(out, f"{nodes} nodes, {T.shape[1]} coordinates,",
          "frequencies (Hz):", " ".join(f"{np.sqrt(x) / (2 * np.pi):.4g}" for x in lam))


if __name__ == "__main__":
    main()
