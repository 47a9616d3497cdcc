#include "engine/io/obj_writer.hpp"

#include <charconv>
#include <ostream>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/io/atomic_file.hpp"

namespace curvefold {
namespace {

// Shortest text that reads back as the same double, so an OBJ round trip is exact.
void writeNumber(std::ostream& out, double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  out << ' ';
  out.write(text, result.ptr - text);
}

}  // namespace

void writeObj(const Sheet& sheet, const std::filesystem::path& path, const ObjOptions& options) {
  std::vector<CreaseCurve> curves;
  if (options.creaseLines) curves = creaseCurves(sheet, buildEdgeTopology(sheet));

  writeFileAtomically(path, [&](std::ostream& out) {
    out << "# curvefold sheet: " << sheet.vertexCount() << " vertices, " << sheet.triangleCount()
        << " triangles\n"
        << "# v = folded position in metres; vt = development (the flat paper) in metres, not\n"
        << "# normalised to [0, 1]\n"
        << "o sheet\n";
    for (const glm::dvec3& p : sheet.positions) {
      out << 'v';
      writeNumber(out, p.x);
      writeNumber(out, p.y);
      writeNumber(out, p.z);
      out << '\n';
    }
    for (const glm::dvec2& p : sheet.development) {
      out << "vt";
      writeNumber(out, p.x);
      writeNumber(out, p.y);
      out << '\n';
    }
    out << "g paper\n";
    for (const Triangle& t : sheet.triangles) {
      out << 'f';
      for (VertexIndex v : t) out << ' ' << v + 1 << '/' << v + 1;  // OBJ counts from 1
      out << '\n';
    }
    if (!curves.empty()) {
      out << "g creases\n";
      for (const CreaseCurve& curve : curves) {
        out << 'l';
        for (VertexIndex v : curve.vertices) out << ' ' << v + 1;
        out << '\n';
      }
    }
  });
}

}  // namespace curvefold
