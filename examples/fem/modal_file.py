"""Craig-Bampton reduction and MBDyn's modal data file, shared by the FE examples (boom_fem.py, panel_fem.py).

The .fem layout unfurl's `flexible: {fem: ...}` reads is in docs/FLEXIBLE.md.
"""
import numpy as np


def generalized_eigen(K, M):
    """Eigenvalues (ascending) and M-orthonormal eigenvectors of K x = lambda M x."""
    L = np.linalg.cholesky(M)
    Linv = np.linalg.inv(L)
    lam, y = np.linalg.eigh(Linv @ K @ Linv.T)
    return lam, Linv.T @ y


def craig_bampton(K, M, held, interface, normal_modes):
    """The reduction basis T (dofs x modes): fixed-interface normal modes, then one constraint mode per interface dof."""
    n = K.shape[0]
    interior = [d for d in range(n) if d not in held and d not in interface]
    _, phi = generalized_eigen(K[np.ix_(interior, interior)], M[np.ix_(interior, interior)])
    T = np.zeros((n, normal_modes + len(interface)))
    T[interior, :normal_modes] = phi[:, :normal_modes]
    psi = -np.linalg.solve(K[np.ix_(interior, interior)], K[np.ix_(interior, interface)])
    T[interior, normal_modes:] = psi
    for c, d in enumerate(interface):
        T[d, normal_modes + c] = 1
    return T


def write_fem(path, title, points, T, Mr, Kr, lumped, normal_modes):
    """MBDyn's modal data file: record groups 1-12, numbers with 16 digits."""
    nodes = points.shape[1]
    modes = T.shape[1]
    mass = lumped[0].sum()
    centre = (points * lumped[0]).sum(axis=1) / mass
    r = points - centre[:, None]
    inertia = sum(lumped[0, k] * (r[:, k] @ r[:, k] * np.eye(3) - np.outer(r[:, k], r[:, k])) for k in range(nodes))
    inertia += np.diag(lumped[3:6].sum(axis=1))

    def row(values):
        return " ".join(f"{v:.16e}" for v in values) + "\n"

    with open(path, "w") as f:
        f.write("** MBDyn MODAL DATA FILE\n")
        f.write(f"** {title}\n")
        f.write("** RECORD GROUP 1, HEADER\n")
        f.write("**   REVISION, NODE, NORMAL, ATTACHMENT, CONSTRAINT, REJECTED MODES\n")
        f.write(f"REV0 {nodes} {normal_modes} 0 {modes - normal_modes} 0\n**\n")
        f.write("** RECORD GROUP 2, FINITE ELEMENT NODE LIST\n")
        f.write(" ".join(str(k + 1) for k in range(nodes)) + "\n**\n")
        f.write("** RECORD GROUP 3, INITIAL MODAL DISPLACEMENTS\n" + row(np.zeros(modes)) + "**\n")
        f.write("** RECORD GROUP 4, INITIAL MODAL VELOCITIES\n" + row(np.zeros(modes)) + "**\n")
        for g, axis in enumerate("XYZ"):
            f.write(f"** RECORD GROUP {5 + g}, NODAL {axis} COORDINATES\n")
            f.writelines(f"{x:.16e}\n" for x in points[g])
            f.write("**\n")
        f.write("** RECORD GROUP 8, MODE SHAPES\n")
        for j in range(modes):
            f.write(f"**    {'NORMAL' if j < normal_modes else 'CONSTRAINT'} MODE SHAPE # {j + 1}\n")
            for k in range(nodes):
                f.write(row(T[6 * k:6 * k + 6, j]))
        f.write("**\n** RECORD GROUP 9, MODAL MASS MATRIX\n")
        f.writelines(row(Mr[i]) for i in range(modes))
        f.write("**\n** RECORD GROUP 10, MODAL STIFFNESS MATRIX\n")
        f.writelines(row(Kr[i]) for i in range(modes))
        f.write("**\n** RECORD GROUP 11, DIAGONAL OF LUMPED MASS MATRIX\n")
        f.writelines(row(lumped[:, k]) for k in range(nodes))
        f.write("**\n** RECORD GROUP 12, RIGID BODY INERTIA MATRIX\n")
        f.write(f"{mass:.16e}\n" + row(centre) + "".join(row(inertia[i]) for i in range(3)))
        f.write("**\n** END OF FILE\n")
