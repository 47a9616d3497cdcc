#!/usr/bin/awk -f
# Saddle targets for `curvefold fit` made apart from curvefold (issue 38, 2), in plain awk, unlike
# scripts/make-example-targets.sh, bench/make_smooth_targets.py and bench/make_saddle_targets.py:
# height along y (not z), triangular lattices clipped to an ellipse, quads split about a centre
# vertex, a scan with noise along its normal and holes. Usage:
#   awk -v out=DIR -f bench/make_saddle_lattice.awk
# writes DIR/hypar_y.obj (y = x z / 0.25 over 30 cm, 24x24, turned 30 degrees about y),
# DIR/pringle.obj (y = u^2/0.5 - v^2/0.3 over a 24 x 16 cm ellipse of triangles, tilted 20
# degrees), DIR/saddle_fan.obj (y = (x^2 - z^2)/0.4 over 40 cm, 6x6 quads each a fan of 4) and
# DIR/hypar_noisy.obj (y = x z / 0.15 over 20 cm, 50x50, noise 0.4 mm, two holes, turned 50).
function gauss() { return sqrt(-2 * log(1 - rand())) * cos(6.283185307179586 * rand()) }
function emit(file, x, y, z, yaw, tilt,   c, s, t) {
  c = cos(yaw); s = sin(yaw); t = x * c + z * s; z = -x * s + z * c; x = t
  c = cos(tilt); s = sin(tilt); t = y * c - z * s; z = y * s + z * c; y = t
  printf "v %.7f %.7f %.7f\n", x, y, z > file
}
function grid(file, n, size, kind, yaw, holes,   i, j, x, z, y, id, a, b, c, d) {
  for (j = 0; j <= n; j++) for (i = 0; i <= n; i++) {
    x = size * (i / n - 0.5); z = size * (j / n - 0.5)
    if (kind == 1) y = x * z / 0.25
    else y = x * z / 0.15 + 0.0004 * gauss()
    emit(file, x, y, z, yaw, 0)
  }
  for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
    if (holes && ((i - 12)^2 + (j - 30)^2 < 16 || (i - 35)^2 + (j - 15)^2 < 9)) continue
    a = j * (n + 1) + i + 1; b = a + 1; c = a + n + 2; d = a + n + 1
    if ((i + j) % 2) { print "f", a, b, c > file; print "f", a, c, d > file }
    else { print "f", a, b, d > file; print "f", b, c, d > file }
  }
  close(file)
}
BEGIN {
  if (out == "") { print "usage: awk -v out=DIR -f make_saddle_lattice.awk" > "/dev/stderr"; exit 1 }
  srand(3817); pi = 3.141592653589793
  grid(out "/hypar_y.obj", 24, 0.3, 1, 30 * pi / 180, 0)
  grid(out "/hypar_noisy.obj", 50, 0.2, 2, 50 * pi / 180, 1)
  # Pringle: a triangular lattice (rows offset by half a step) clipped to the ellipse.
  f = out "/pringle.obj"; h = 0.008; nv = 0
  for (r = -12; r <= 12; r++) for (q = -16; q <= 16; q++) {
    u = (q + (r % 2 ? 0.5 : 0)) * h; v = r * h * 0.8660254
    if ((u / 0.12)^2 + (v / 0.08)^2 > 1) continue
    idx[r, q] = ++nv; emit(f, u, u * u / 0.5 - v * v / 0.3, v, 0, 20 * pi / 180)
  }
  for (r = -12; r < 12; r++) for (q = -16; q < 16; q++) {
    # Row r's vertex q sits between row r+1's q and q+1 when r is even, q-1 and q when odd.
    o = (r % 2 ? 1 : 0)
    if ((r, q) in idx && (r, q + 1) in idx && (r + 1, q + o) in idx)
      print "f", idx[r, q], idx[r, q + 1], idx[r + 1, q + o] > f
    if ((r, q + 1) in idx && (r + 1, q + 1 + o) in idx && (r + 1, q + o) in idx)
      print "f", idx[r, q + 1], idx[r + 1, q + 1 + o], idx[r + 1, q + o] > f
  }
  close(f)
  # Saddle fan: 6x6 quads over 40 cm, each split into 4 about its centre.
  f = out "/saddle_fan.obj"; n = 6; s = 0.4
  for (j = 0; j <= n; j++) for (i = 0; i <= n; i++) {
    x = s * (i / n - 0.5); z = s * (j / n - 0.5); emit(f, x, (x * x - z * z) / 0.4, z, 0, 0)
  }
  nv = (n + 1) * (n + 1)
  for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
    x = s * ((i + 0.5) / n - 0.5); z = s * ((j + 0.5) / n - 0.5)
    emit(f, x, (x * x - z * z) / 0.4, z, 0, 0); m = ++nv
    a = j * (n + 1) + i + 1; b = a + 1; c = a + n + 2; d = a + n + 1
    print "f", a, b, m > f; print "f", b, c, m > f; print "f", c, d, m > f; print "f", d, a, m > f
  }
  close(f)
}
