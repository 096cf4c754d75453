"""Helpers shared by the test drivers: run tribos, read its CSV output,
compare with references through numdiff, report a check, a skip or a
rewritten reference. Standard library only.

ctest puts tests/ (this package), tools/ and benchmarks/peers/ on
PYTHONPATH; to run a driver by hand:

    PYTHONPATH=tests:tools:benchmarks/peers python3 \
        tests/verification/hertz.py build/tribos tests/data /tmp/hertz"""

from . import analytic
import atexit
import collections
import bisect
import csv
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

#: The repository's folders the drivers read beside tests/data.
REPOSITORY = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
PARAMETERS = os.path.join(REPOSITORY, "parameters")

#: The exit code ctest reports as "skipped" (SKIP_RETURN_CODE).
SKIPPED = 77


def setup(argv):
    """Return (tribos executable, tests folder, fresh output folder)."""
    tribos, tests, out = argv[1], argv[2], argv[3]
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    return tribos, tests, out


def run(tribos, prm, out, sets=(), mpi_ranks=0, expect_success=True,
        extra=()):
    """Run tribos on prm with output into out, the --set overrides and the
    extra arguments."""
    command = [tribos, prm, "--set", "Output/Directory=" + out]
    for s in sets:
        command += ["--set", s]
    command += list(extra)
    if mpi_ranks:
        command = [os.environ.get("MPIEXEC", "mpirun"), "-np",
                   str(mpi_ranks)] + command
        result = _timed(lambda: subprocess.run(command, capture_output=True,
                                               text=True), command, "mpirun")
    else:
        result = _served(command)
    if expect_success and result.returncode != 0:
        print(result.stdout)
        print(result.stderr)
        raise SystemExit("tribos failed with exit code %d: %s"
                         % (result.returncode, " ".join(command)))
    return result


_servers = {}


def _served(command):
    """subprocess.run(command, capture_output=True, text=True) for a
    serial run of tribos, by a child of `tribos --fork-server` (see
    include/tribos/base/fork_server.h): the same program and command line
    in a process of its own, but without the half second the dynamic
    linker takes to load deal.II's libraries each time. The server is
    started at the first run of each executable and ends with the driver.
    Only with TRIBOS_TEST_FORK_SERVER=1 (ctest sets it: the test suite);
    otherwise, and for the benchmarks, whose peak memory must count the
    libraries, every run starts from scratch."""
    environment = ["%s=%s" % item for item in os.environ.items()]
    lines = [os.getcwd()] + environment + command[1:]
    if os.environ.get("TRIBOS_TEST_FORK_SERVER") != "1" or \
            any("\n" in line for line in lines):
        return _timed(lambda: subprocess.run(command, capture_output=True,
                                             text=True), command, "process")
    return _timed(lambda: _fork(command, environment), command, "forked")


def _fork(command, environment):
    """The run of command as a child of this executable's server."""
    server = _servers.get(command[0])
    if server is None or server.poll() is not None:
        server = subprocess.Popen([command[0], "--fork-server"],
                                  stdin=subprocess.PIPE,
                                  stdout=subprocess.PIPE, text=True)
        _servers[command[0]] = server
    with tempfile.TemporaryDirectory() as folder:
        out, err = folder + "/stdout", folder + "/stderr"
        request = ["run %d" % (len(command) - 1), os.getcwd(), out, err,
                   str(len(environment))] + environment + command[1:]
        server.stdin.write("\n".join(request) + "\n")
        server.stdin.flush()
        status = server.stdout.readline().split()
        if len(status) != 2 or status[0] not in ("exit", "signal"):
            raise SystemExit("FAILED  tribos --fork-server answered %r to %s"
                             % (" ".join(status), " ".join(command)))
        code = int(status[1]) if status[0] == "exit" else -int(status[1])
        with open(out, errors="replace") as f:
            stdout = f.read()
        with open(err, errors="replace") as f:
            stderr = f.read()
    return subprocess.CompletedProcess(command, code, stdout, stderr)


def _timed(launch, command, how):
    """launch() (a run of command, started as how says: "process",
    "forked" or "mpirun"); with $TRIBOS_TEST_RUN_LOG set, append to that
    CSV file the driver, its case, how, the run's wall seconds and the
    command: where a test's time goes."""
    log = os.environ.get("TRIBOS_TEST_RUN_LOG")
    if not log:
        return launch()
    start = time.perf_counter()
    result = launch()
    wall = time.perf_counter() - start
    driver = os.path.splitext(os.path.basename(sys.argv[0]))[0]
    case = sys.argv[4] if len(sys.argv) > 4 else ""
    with open(log, "a") as f:
        f.write("%s,%s,%s,%.3f,\"%s\"\n" % (
            driver, case, how, wall, " ".join(command).replace('"', "'")))
    return result


@atexit.register
def _stop_servers():
    """End the fork servers (their input closed) with the driver."""
    for server in _servers.values():
        server.stdin.close()
        server.wait()


def run_or_hang(tribos, prm, out, sets=(), mpi_ranks=0, timeout=120):
    """Run tribos like run() but expecting it may fail or hang: the
    CompletedProcess (stdout and stderr together in .stdout), or a test
    failure if the run does not end within timeout seconds. The run gets a
    session of its own, so that a hung run's processes can all be killed
    (mpirun does not pass on SIGKILL)."""
    command = [tribos, prm, "--set", "Output/Directory=" + out]
    for s in sets:
        command += ["--set", s]
    if mpi_ranks:
        command = [os.environ.get("MPIEXEC", "mpirun"), "-np",
                   str(mpi_ranks)] + command
    process = subprocess.Popen(command, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True,
                               start_new_session=True)
    try:
        output = process.communicate(timeout=timeout)[0]
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        raise SystemExit("FAILED  %d process(es): the run hangs (no end "
                         "in %d s)" % (max(mpi_ranks, 1), timeout))
    return subprocess.CompletedProcess(command, process.returncode, output)


def mpi_available():
    """Whether mpirun (or $MPIEXEC) is installed; if so, let it run as root
    and oversubscribe a small machine (unless the environment says
    otherwise)."""
    if shutil.which(os.environ.get("MPIEXEC", "mpirun")) is None:
        return False
    for variable in ("OMPI_ALLOW_RUN_AS_ROOT", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM",
                     "OMPI_MCA_rmaps_base_oversubscribe"):
        os.environ.setdefault(variable, "1")
    return True


def solver_line(folder):
    """The linear solver summary.txt reports ("" if none)."""
    with open(folder + "/summary.txt") as f:
        for line in f:
            if line.startswith("linear solver"):
                return line.split(None, 2)[2].strip()
    return ""


def read_csv(path):
    """Rows of a CSV file as a list of dicts of floats."""
    with open(path) as f:
        return [{k: float(v) if v not in ("", "nan") else math.nan
                 for k, v in row.items()} for row in csv.DictReader(f)]


def strip_columns(source, target, drop=("wall_time",)):
    """Copy a CSV without the columns that differ from run to run."""
    with open(source) as f:
        rows = list(csv.reader(f))
    keep = [i for i, name in enumerate(rows[0]) if name not in drop]
    with open(target, "w") as f:
        for row in rows:
            f.write(",".join(row[i] for i in keep) + "\n")


def numdiff(result, reference, relative=1e-6, absolute=1e-10):
    """Compare two files with numdiff; raise with its output on mismatch."""
    command = [os.environ.get("NUMDIFF", "numdiff"), "-q", "-s", ", \n",
               "-r", str(relative), "-a", str(absolute), result, reference]
    outcome = subprocess.run(command, capture_output=True, text=True)
    if outcome.returncode != 0:
        full = subprocess.run(command[:1] + command[2:], capture_output=True,
                              text=True)
        print(full.stdout[-4000:])
        raise SystemExit("numdiff: %s differs from %s" % (result, reference))


def identical_rows(result, reference, drop=("wall_time",)):
    """Whether two CSV files hold the same text in every column but drop;
    prints the first row that differs. What a restart on as many
    processes as the run that wrote the checkpoint claims: bit for bit
    (every number in the digits written), residual norms and iteration
    counts included, whatever BLAS kernels run."""
    tables = []
    for path in (result, reference):
        with open(path) as f:
            rows = list(csv.reader(f))
        keep = [i for i, name in enumerate(rows[0]) if name not in drop]
        tables.append([[row[i] for i in keep] for row in rows])
    if tables[0] == tables[1]:
        return True
    for n, (a, b) in enumerate(zip(*tables)):
        if a != b:
            columns = [tables[1][0][i] for i in range(len(a))
                       if i >= len(b) or a[i] != b[i]]
            print("%s line %d differs from %s in %s:\n  %s\n  %s"
                  % (result, n + 1, reference, ", ".join(columns),
                     ",".join(a), ",".join(b)))
            return False
    print("%s has %d lines, %s %d" % (result, len(tables[0]), reference,
                                       len(tables[1])))
    return False


def restart_identical(reference, restarted):
    """Whether a restarted run's history.csv (but its wall times) and last
    contact CSV equal the uninterrupted run's to the last digit."""
    contact = sorted(f for f in os.listdir(reference)
                     if f.startswith("contact-"))[-1:]
    return all([identical_rows(restarted + "/history.csv",
                               reference + "/history.csv")] +
               [identical_rows(restarted + "/" + f, reference + "/" + f,
                               drop=()) for f in contact])


#: What Newton's tolerances (Nonlinear solver/Increment tolerance, 1e-8 by
#: default) allow two runs of the same increments to differ by, relative
#: to the values: each stops when its remaining error is below the
#: tolerance times the increment's change, so they differ by at most
#: twice that. A restart on another number of processes (other rounding
#: in every solve) is bounded by this, not by the digits.
NEWTON_AGREEMENT = 2e-8


def restart_agrees(reference, restarted):
    """A restart on another number of processes: history.csv (without
    wall times, residual norms and iteration counts, which rounding may
    change) and the last contact CSV equal to NEWTON_AGREEMENT, relative
    to each value or to the largest value of its kind in the file (the
    forces, the tractions, the lengths: a value near zero, a reaction's
    tangential part or the penetration under multipliers, differs by the
    rounding of the large ones of its kind). Raises on a difference."""
    drop = ("wall_time", "residual", "newton_iterations",
            "newton_iterations_all", "energy_error")

    def kind(column):
        if column.startswith(("RF", "pair")):
            return "force"
        if column.startswith(("CPRESS", "CSHEAR")):
            return "traction"
        if column in ("x", "y", "z", "X", "Y", "Z", "COPEN", "CSLIP",
                      "max_penetration"):
            return "length"
        return column

    files = ["history.csv"] + sorted(f for f in os.listdir(reference)
                                     if f.startswith("contact-"))[-1:]
    tables = {f: [read_csv(folder + "/" + f) for folder in (reference,
                                                             restarted)]
              for f in files}
    # One scale per kind over both files (the contact file's coordinates
    # are the lengths' scale of the history's penetration too).
    scale = collections.defaultdict(float)
    for rows in tables.values():
        for row in rows[0]:
            for k, v in row.items():
                if not math.isnan(v):
                    scale[kind(k)] = max(scale[kind(k)], abs(v))
    for f, rows in tables.items():
        if len(rows[0]) != len(rows[1]):
            raise SystemExit("%s/%s has %d rows, the uninterrupted run's %d"
                             % (restarted, f, len(rows[1]), len(rows[0])))
        for n, (a, b) in enumerate(zip(rows[1], rows[0])):
            for k in b:
                if k in drop or (math.isnan(a[k]) and math.isnan(b[k])):
                    continue
                bound = NEWTON_AGREEMENT * max(abs(b[k]), scale[kind(k)])
                if not abs(a[k] - b[k]) <= bound:
                    raise SystemExit(
                        "%s/%s row %d, %s: %.12g against %.12g (bound %.1e)"
                        % (restarted, f, n + 1, k, a[k], b[k], bound))


def sphere_on_block(level, discretization):
    """--set overrides of parameters/hertz_3d.prm for the quarter sphere
    pressed 0.02 into an elastic block of its material (penalty 1000 E/h),
    Contact refinements = level."""
    return ["Scene/Cylinder over block/With block=true",
            "Scene/Cylinder over block/Contact refinements=%d" % level,
            "Contact/Pairs=10 : 5",
            "Boundary conditions/Symmetry=12, 13, 0, 2",
            "Boundary conditions/Dirichlet=11 : z : -0.02*t ; "
            "4 : xyz : 0, 0, 0",
            "Contact/Penalty factor=1000*E/h",
            "Contact/Discretization=" + discretization]


def hertz_compare(folder, dim, e_star, radius, force_scale, step=2,
                  reference=False):
    """Hertz values for the contact normal force of a run (times
    force_scale for symmetry models) against the fit of its nodal pressures
    at output step `step`: returns (a, p0, fitted a, fitted p0, relative L2
    error of the pressure profile, number of nodes in contact). 2D: a =
    sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a); 3D: a = (3 P R / (4 E*))^(1/3),
    p0 = 3 P / (2 pi a^2). reference: positions from the reference
    coordinates (X, Y) instead of the deformed ones (Hertz's theory is
    geometrically linear; at p0 = 0.06 E the two differ by about
    nu p0 / E of the distance from the centre)."""
    history = read_csv(folder + "/history.csv")[-1]
    P = history["pair0_normal_force"] * force_scale
    a, p0 = analytic.hertz(P, radius, e_star, dim)
    p0_h, a_h, points = hertz_fit(
        read_csv(folder + "/contact-%05d.csv" % step), dim, reference)
    profile = math.sqrt(
        sum((p - p0 * math.sqrt(max(0.0, 1 - x * x / (a * a)))) ** 2
            for x, p in points) / sum(p * p for x, p in points))
    return a, p0, a_h, p0_h, profile, len(points), P


def profile_difference(rows, reference):
    """Relative L2 difference of a 2D pressure profile (contact-NNNNN.csv
    rows: CPRESS against the deformed x) from a reference profile (rows
    with x and CPRESS, e.g. a run on a much finer mesh), both linear
    between their nodes, integrated over 1.2 times the reference's contact
    zone (4 001 points)."""
    def linear(points):
        points = sorted(points)
        xs = [x for x, _ in points]

        def at(x):
            if x <= xs[0] or x >= xs[-1]:
                return 0.0
            i = bisect.bisect_right(xs, x)
            (x0, p0), (x1, p1) = points[i - 1], points[i]
            return p0 + (p1 - p0) * (x - x0) / (x1 - x0)
        return at
    exact = linear([(r["x"], r["CPRESS"]) for r in reference])
    mine = linear([(r["x"], r["CPRESS"]) for r in rows])
    a = max(abs(r["x"]) for r in reference if r["CPRESS"] > 0)
    xs = [-1.2 * a + 2.4 * a * i / 4000 for i in range(4001)]
    return math.sqrt(sum((mine(x) - exact(x)) ** 2 for x in xs) /
                     sum(exact(x) ** 2 for x in xs))


def hertz_fit(rows, dim, reference=False):
    """Hertz p0 and a fitted to contact-NNNNN.csv rows: least squares of
    p^2 = p0^2 (1 - r^2/a^2) over the nodes in contact (r = |x| in 2D,
    the distance from the z axis in 3D); also returns the (r, p) points."""
    x, y = ("X", "Y") if reference else ("x", "y")
    points = []
    for r in rows:
        if r["CPRESS"] > 0:
            radius = math.hypot(r[x], r[y]) if dim == 3 else abs(r[x])
            points.append((radius, r["CPRESS"]))
    n = len(points)
    sx = sum(p[0] ** 2 for p in points)
    sy = sum(p[1] ** 2 for p in points)
    sxx = sum(p[0] ** 4 for p in points)
    sxy = sum(p[0] ** 2 * p[1] ** 2 for p in points)
    slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
    intercept = (sy - slope * sx) / n
    return math.sqrt(intercept), math.sqrt(-intercept / slope), points


def iteration_counts(folder):
    """(increments, cutbacks, Newton iterations with the failed attempts)
    of the run in folder, from its history.csv (whose cutbacks column
    counts a step's cutbacks so far)."""
    rows = read_csv(folder + "/history.csv")
    cutbacks = sum(int(max(r["cutbacks"] for r in rows if r["step"] == s))
                   for s in set(r["step"] for r in rows))
    return (len(rows), cutbacks,
            int(sum(r["newton_iterations_all"] for r in rows)))


def recorded_budgets():
    """The table under "## Iteration budgets" in doc/robustness.md: per
    case name (its first column) the increments, cutbacks and Newton
    iterations (all attempts) recorded there."""
    budgets, inside = {}, False
    for line in open(os.path.join(REPOSITORY, "doc", "robustness.md")):
        if line.startswith("## "):
            inside = line.strip() == "## Iteration budgets"
        elif inside and line.startswith("| `"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            budgets[cells[0].strip("`")] = tuple(int(c) for c in cells[1:4])
    return budgets


def iteration_budget(name, folder):
    """Check the run in folder against its budget, the row @p name of
    doc/robustness.md's "Iteration budgets": increments, cutbacks and
    Newton iterations each within 10 % (at least 1) of the recorded
    numbers, so that a change that costs (or saves) iterations shows."""
    measured = iteration_counts(folder)
    recorded = recorded_budgets().get(name)
    within = recorded is not None and all(
        abs(m - r) <= max(0.1 * r, 1) for m, r in zip(measured, recorded))
    check(within, "%s: %d increments, %d cutbacks, %d Newton iterations; "
          "recorded in doc/robustness.md %s (within 10 %%)"
          % ((name,) + measured +
             ("%d / %d / %d" % recorded if recorded else "nothing",)))


def check(condition, message):
    """Print the check and fail the test if it does not hold."""
    print(("ok      " if condition else "FAILED  ") + message)
    if not condition:
        check.failed = True


check.failed = False


def skip(message):
    """Print that a part of the test did not run (e.g. no mpirun): the
    test then ends as skipped, never as passed, unless a check failed."""
    print("SKIPPED " + message)
    skip.parts.append(message)


skip.parts = []


def require_mpi():
    """End the test as skipped if mpirun is not installed."""
    if not mpi_available():
        skip("mpirun (or $MPIEXEC) not found")
        finish()


def parts(argv, names):
    """The parts of a driver split into ctest cases (its "# ctest: cases"
    line): the one argv[4] names, or all of them when it names none (a run
    by hand)."""
    if len(argv) > 4:
        if argv[4] not in names:
            raise SystemExit("unknown case <%s>; the cases are %s"
                             % (argv[4], ", ".join(names)))
        return {argv[4]}
    return set(names)


def mpi_part(selected, what="the MPI runs"):
    """Whether the MPI part of a split driver runs: if mpirun is missing,
    the part is reported as skipped, and a test that is that part alone
    (selected == {"mpi"}) ends there as skipped."""
    if mpi_available():
        return True
    skip("%s: mpirun (or $MPIEXEC) not found" % what)
    if selected == {"mpi"}:
        finish()
    return False


def updating_references():
    """Whether TRIBOS_UPDATE_REFERENCES=1 asks to rewrite the references
    (after a change that is understood and intended)."""
    return os.environ.get("TRIBOS_UPDATE_REFERENCES") == "1"


def reference_updated(path):
    """Report that the reference path was rewritten from this run: the
    test then fails, since a comparison with what was just written cannot
    check anything; run it again without TRIBOS_UPDATE_REFERENCES."""
    print("UPDATED " + path)
    reference_updated.paths.append(path)


reference_updated.paths = []


def finish():
    """Exit 1 if a check failed or a reference was rewritten, 77 (skipped)
    if a part of the test did not run, 0 if every check ran and held."""
    if reference_updated.paths:
        print("FAILED  %d reference(s) rewritten, nothing compared: review "
              "the difference (git diff) and run the test again"
              % len(reference_updated.paths))
        sys.exit(1)
    if check.failed:
        sys.exit(1)
    sys.exit(SKIPPED if skip.parts else 0)
