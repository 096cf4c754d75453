"""The assembled tangent against central finite differences of the
assembled residual (Nonlinear solver/Check tangent) in every Newton
iteration of two sliding runs where slave nodes cross master faces: the
2D ironing scene (deformable curved slave on a deformable master) and
3D frictional block-on-block sliding (bilinear master faces). Asserts a
relative error below 1e-6 everywhere (columns of all contact dofs and
every 7th dof)."""

import re
import sys

from tribos_test import setup, run, check, finish

tribos, tests, out = setup(sys.argv)
for name, sets in (("ironing_2d", ["Time stepping/End time=1.5",
                                   "Time stepping/Number of steps=6"]),
                   ("sliding_blocks_3d", [])):
    result = run(tribos, "%s/%s.prm" % (tests, name), out + "/" + name,
                 sets + ["Nonlinear solver/Check tangent=true"])
    errors = [float(e) for e in
              re.findall(r"tangent check, iteration \d+: relative error (\S+)",
                         result.stdout)]
    check(len(errors) > 10 and max(errors) < 1e-6,
          "%s: %d checks, max relative tangent error %.2e < 1e-6"
          % (name, len(errors), max(errors)))
finish()
