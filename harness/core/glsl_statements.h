#pragma once
// The statements of a GLSL function's body, read as text (comments
// blanked), with the lines they start and end on: enough to find the
// locals a fragment shader computes and where, for `snell init`'s captures.
#include <cstddef>
#include <string>
#include <vector>

namespace snell {

struct GlslStatement {
  std::string text;   // the statement without its `;`, whitespace runs kept
  int firstLine = 0;  // where its first character is
  int lastLine = 0;   // where its `;` is: the line a fragment capture names
  int depth = 0;      // blocks it is nested in inside main() (0: main's own)
};

// The statements of `void main()`, in order, nested blocks' included (a
// local declared in one is in scope to the block's end); a block's header
// (`if (...)`, `for (...)`) is not one. Empty when the source has no main().
std::vector<GlslStatement> mainStatements(const std::string& source);

// Where `void main()`'s body starts in `text` (comments blanked): just
// after its `{`; npos when there is none.
std::size_t mainBody(const std::string& text);

// The identifiers of `text` in order, each once.
std::vector<std::string> identifiersIn(const std::string& text);

}  // namespace snell
