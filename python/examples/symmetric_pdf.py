"""A symmetric design written to a PDF to print: a cylinder whose every fold brings its five
images (rotational:6), two folds at the rim, the crease pattern tiled at real size on A4.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/symmetric_pdf.py [OUT.pdf]
"""

import sys

import curvefold

out = sys.argv[1] if len(sys.argv) > 1 else "crown.pdf"
design = curvefold.Design.new("cylinder", resolution=72, symmetry="rotational:6:y")
for grab, to in [((0.0, 0.105, 0.045), (0.0, 0.085, 0.03)),
                 ((0.0, -0.105, 0.045), (0.0, -0.09, 0.035))]:
    result = design.fold(grab=grab, to=to)
    print(f"fold: {result.images} images, {result.triangles} triangles {result.notes}".rstrip())
check = design.check()
print("check:", "passed" if check.passed else check.failures)
design.export(pdf=out, angles=True)
print("wrote", out)
