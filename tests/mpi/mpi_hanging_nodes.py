"""MPI on a distributed mesh with hanging nodes at a symmetry plane and on
the contact surface: `mpirun -np 2, 3, 4` give the serial nodal pressures,
positions and history to 1e-9 relative.

The 3D patch test (tests/data/patch_test_3d.prm: symmetry on x = 0, y = 0,
z = 0, a uniform pressure on the top) with the upper block's first column
of cells refined once (Scene/Two blocks/Refinement box): its refinement
border has hanging nodes on the slave surface, on the loaded top and on
the symmetry plane y = 0. On a distributed mesh the outer faces of a
process's ghost layer are boundary faces of the local mesh with id 0, and
boundary 0 is a symmetry plane here: the symmetry constraints a process
computes for dofs at the edge of its ghost layer are wrong, and where such
a dof is a parent of a hanging node the process owns, the wrong line
must not reach the hanging node's (a parent's weight vanished, and the
pressures were 1e-4 off the serial run at -np 2 and 4). Node to segment
with penalty and mortar with dual multipliers (the hanging node's
multiplier function carried by its parents, whose values it reports:
with -np 3 some of them belong to another process). Every slave node is
closed."""
# ctest: mpirun

import sys

from tribos_testing import (require_mpi, setup, run, read_csv, check, finish, mpi_available,
                         strip_columns, numdiff)

tribos, tests, out = setup(sys.argv)
prm = tests + "/patch_test_3d.prm"
refined = ["Scene/Two blocks/Refinement box=0.1, 0.1, 0.5 : 0.45, 0.9, 1",
           "Scene/Two blocks/Lower subdivisions=5, 5, 2",
           "Parallel/Mesh=distributed"]
noisy = ("wall_time", "residual", "newton_iterations",
         "newton_iterations_all", "chattering_nodes")


def nodes(folder):
    """Slave node rows of the contact CSV, keyed by reference position."""
    return {(r["pair"], round(r["X"], 9), round(r["Y"], 9), round(r["Z"], 9)):
            r for r in read_csv(folder + "/contact-00001.csv")}


require_mpi()

for method, discretization, all_ranks in (
        ("penalty", "node to segment", (2, 3, 4)),
        ("lagrange multiplier", "mortar", (2, 3))):
    sets = refined + ["Contact/Method=" + method,
                      "Contact/Discretization=" + discretization]
    name = "%s_%s" % (discretization.replace(" ", "_"),
                      method.replace(" ", "_"))
    serial = out + "/" + name + "_np1"
    run(tribos, prm, serial, sets)
    reference = nodes(serial)
    strip_columns(serial + "/history.csv", serial + "/h.csv", drop=noisy)
    for ranks in all_ranks:
        folder = "%s/%s_np%d" % (out, name, ranks)
        run(tribos, prm, folder, sets, mpi_ranks=ranks)
        result = nodes(folder)
        scale = max(abs(r["CPRESS"]) for r in reference.values())
        worst_p = max(abs(result[k]["CPRESS"] - r["CPRESS"]) / scale
                      for k, r in reference.items() if k in result)
        worst_x = max(abs(result[k][c] - r[c])
                      for k, r in reference.items() if k in result
                      for c in ("x", "y", "z"))
        n_open = sum(r["CSTATUS"] == 0 for r in result.values())
        check(set(result) == set(reference) and worst_p < 1e-9 and
              worst_x < 1e-9 and n_open == 0,
              "%s, distributed mesh, -np %d: %d slave nodes as in the "
              "serial run, pressures within %.1e of the largest, positions "
              "within %.1e, %d open" % (name, ranks, len(result), worst_p,
                                        worst_x, n_open))
        strip_columns(folder + "/history.csv", folder + "/h.csv", drop=noisy)
        numdiff(folder + "/h.csv", serial + "/h.csv", relative=1e-9,
                absolute=1e-12)
        print("ok      %s, -np %d: the serial history" % (name, ranks))
finish()
