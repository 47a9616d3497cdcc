// A design's printed cover (the first page of `writeCreasePatternPdf`), the same from every
// front end that prints one: the command line's `export --pdf` and the Python module's
// Design.export(pdf=...) (issue 41, 3): the facts (cover_facts.hpp: surface and symmetry, folds,
// today's date) and the folded form in the iso view, rendered headless (Vulkan).
#pragma once

#include <optional>
#include <string>

#include "app/session/cover_facts.hpp"
#include "engine/fabrication/crease_pattern_pdf.hpp"
#include "engine/geometry/sheet.hpp"
#include "engine/io/design_document.hpp"

namespace curvefold {
class VulkanContext;
}

namespace curvefold::session {

// The folded form, iso view, 1200x800, for the cover; nothing when it cannot be rendered (no
// Vulkan device, out of memory), and why in `problem` (the front end words it).
std::optional<PdfPicture> renderFoldedForm(const Sheet& sheet, std::string& problem);

// With CURVEFOLD_VK_VALIDATION=1 a validation message is an error (VulkanError naming the count
// and the first), so tests of the front ends catch them too.
void checkValidation(const VulkanContext& context);

}  // namespace curvefold::session
