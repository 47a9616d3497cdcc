// What a design's printed cover says (the first page of `writeCreasePatternPdf`), the same from
// every front end that prints one: `curvefold export --pdf`, Python's Design.export(pdf=...) and
// the studio panel's PDF button (issue 41). Here in the session library, apart from the picture
// (printed_cover.hpp, which renders): the studio prints these facts without linking a renderer,
// its host draws the picture with its own.
#pragma once

#include <string>
#include <vector>

#include "engine/io/design_document.hpp"

namespace curvefold::session {

// The local date, YYYY-MM-DD, for a printed page.
std::string today();

// What the cover says of a design: "surface: NAME[, SYMMETRY]", "folds: N", "date: YYYY-MM-DD".
std::vector<std::string> coverFacts(const Design& design);

}  // namespace curvefold::session
