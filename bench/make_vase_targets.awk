#!/usr/bin/awk -f
# Vases for `fit` (issue 38, 2), made apart from curvefold and unlike the other generators
# (scripts/make-example-targets.sh: one sine formula about y; bench/make_smooth_targets.py: numpy;
# bench/make_revolution_targets.py: Catmull-Rom splines, staggered rings): POSIX awk only, profiles
# as cubic Bezier curves (radius against height, sampled evenly in the curve's parameter, not in
# height) or sums of sines, quads cut along alternating diagonals, axes along x, z or tilted, and
# one coarse 8-sided mesh beside fine ones. Sizes in metres.
#
# Usage: awk -f bench/make_vase_targets.awk -v out=DIR
# Writes DIR/bezier_vase_x.obj (belly, neck and lip, axis along x), sine_lampshade_tilted.obj (a
# bulge, axis tilted 35 degrees), octagon_neck_coarse.obj (8 sides, 9 rings: a shoulder into a
# neck), amphora_based.obj (closed by a flat base, axis along z, 96 x 64).
function bezier(t, p0, p1, p2, p3,   s) {
  s = 1 - t
  return s * s * s * p0 + 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t * p3
}
# The profile of shape `name` at parameter v in [0, 1]: sets H (height along the axis) and R.
function profile(name, v) {
  if (name == "bezier_vase_x") {
    # Two cubic Bezier pieces joined smoothly: base 5 cm to a belly of 8 cm, then a neck of 2.5
    # cm and a lip of 4 cm; 26 cm tall.
    if (v < 0.5) {
      t = v / 0.5
      H = bezier(t, 0.0, 0.03, 0.08, 0.12); R = bezier(t, 0.05, 0.085, 0.085, 0.06)
    } else {
      t = (v - 0.5) / 0.5
      H = bezier(t, 0.12, 0.16, 0.20, 0.26); R = bezier(t, 0.06, 0.035, 0.02, 0.04)
    }
  } else if (name == "sine_lampshade_tilted") {
    # A drum 20 cm tall, radius 10 cm at its ends bulging to 12.5 cm, with a ripple.
    H = 0.2 * v; R = 0.10 + 0.025 * sin(PI * v) + 0.003 * sin(5 * PI * v)
  } else if (name == "octagon_neck_coarse") {
    # A bottle: body 6 cm, shoulder, neck 2.2 cm; 18 cm tall.
    H = 0.18 * v; R = 0.06 - 0.038 / (1 + exp(-(v - 0.62) * 14))
  } else if (name == "amphora_based") {
    # An amphora 30 cm tall: a narrow foot, a wide belly, a neck and a rolled lip.
    H = 0.3 * v
    R = 0.045 + 0.05 * sin(PI * v ^ 0.8) - 0.025 * v + 0.012 * exp(-((v - 1) / 0.06) ^ 2)
  }
}
# Axis frame: unit axis (AX, AY, AZ) and two unit vectors across it, from a tilt of `degrees`
# of the axis `base` ("x", "y" or "z") about the unit vector (kx, ky, kz).
function frame(base, degrees, kx, ky, kz,   c, s, n, ux, uy, uz) {
  if (base == "x") { AX = 1; AY = 0; AZ = 0 } else if (base == "y") { AX = 0; AY = 1; AZ = 0 }
  else { AX = 0; AY = 0; AZ = 1 }
  n = sqrt(kx * kx + ky * ky + kz * kz); kx /= n; ky /= n; kz /= n
  c = cos(degrees * PI / 180); s = sin(degrees * PI / 180)
  # Rodrigues' rotation of the axis about k.
  d = kx * AX + ky * AY + kz * AZ
  cx = ky * AZ - kz * AY; cy = kz * AX - kx * AZ; cz = kx * AY - ky * AX
  AX = AX * c + cx * s + kx * d * (1 - c); AY = AY * c + cy * s + ky * d * (1 - c)
  AZ = AZ * c + cz * s + kz * d * (1 - c)
  # U: any unit vector across the axis; V = axis x U.
  if (AX * AX < 0.8) { ux = 1; uy = 0; uz = 0 } else { ux = 0; uy = 1; uz = 0 }
  d = ux * AX + uy * AY + uz * AZ; ux -= d * AX; uy -= d * AY; uz -= d * AZ
  n = sqrt(ux * ux + uy * uy + uz * uz); UX = ux / n; UY = uy / n; UZ = uz / n
  VX = AY * UZ - AZ * UY; VY = AZ * UX - AX * UZ; VZ = AX * UY - AY * UX
}
function point(h, r, a, file) {
  printf "v %.9g %.9g %.9g\n", OX + h * AX + r * (cos(a) * UX + sin(a) * VX),
         OY + h * AY + r * (cos(a) * UY + sin(a) * VY), OZ + h * AZ + r * (cos(a) * UZ + sin(a) * VZ) > file
}
# A tube of `around` x `along` quads about the current frame; with `base`, a fan closing its start.
function vase(name, around, along, base,   file, i, j, k, a, tmp) {
  file = out "/" name ".obj.tmp"
  printf "# %s: made by bench/make_vase_targets.awk (awk, not curvefold)\n", name > file
  for (j = 0; j <= along; j++) {
    profile(name, j / along)
    for (i = 0; i < around; i++) point(H, R, 2 * PI * i / around, file)
  }
  for (j = 0; j < along; j++)
    for (i = 0; i < around; i++) {
      k = j * around + i + 1; k1 = j * around + (i + 1) % around + 1
      if ((i + j) % 2 == 0)
        printf "f %d %d %d\nf %d %d %d\n", k, k1, k1 + around, k, k1 + around, k + around > file
      else
        printf "f %d %d %d\nf %d %d %d\n", k, k1, k + around, k1, k1 + around, k + around > file
    }
  if (base) {  # a flat base: a centre vertex and a fan onto the first ring, facing out
    profile(name, 0)
    point(H, 0, 0, file)
    c = (along + 1) * around + 1
    for (i = 0; i < around; i++) printf "f %d %d %d\n", c, (i + 1) % around + 1, i + 1 > file
  }
  close(file)
  system("mv '" file "' '" out "/" name ".obj'")
  print "wrote " out "/" name ".obj"
}
BEGIN {
  PI = atan2(0, -1)
  if (out == "") { print "usage: awk -f make_vase_targets.awk -v out=DIR" > "/dev/stderr"; exit 2 }
  system("mkdir -p '" out "'")
  OX = 0.02; OY = -0.01; OZ = 0.03; frame("x", 0, 0, 0, 1); vase("bezier_vase_x", 72, 48, 0)
  OX = 0; OY = 0; OZ = 0; frame("y", 35, 1, 0, 1); vase("sine_lampshade_tilted", 60, 30, 0)
  OX = 0; OY = -0.09; OZ = 0; frame("y", 0, 0, 0, 1); vase("octagon_neck_coarse", 8, 9, 0)
  OX = 0.1; OY = 0.05; OZ = -0.15; frame("z", 0, 1, 0, 0); vase("amphora_based", 96, 64, 1)
}
