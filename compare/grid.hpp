// Tables of text cells as aligned text and as Markdown, shared by the modal and the
// nonlinear comparison tables. The first row is the header.
#pragma once

#include <string>
#include <vector>

namespace cmp {

using Cells = std::vector<std::vector<std::string>>;

/// Right-aligned columns two spaces apart, a rule of dashes under the header.
std::string text_grid(const Cells& c);
/// A Markdown table; the first `left` columns left-aligned, the others right-aligned.
std::string markdown_grid(const Cells& c, std::size_t left = 0);

}  // namespace cmp
