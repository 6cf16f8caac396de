// libFuzzer harness: the TetGen reader. The input holds the .node, .ele, .face and
// .edge texts one after the other, separated by lines "%%" (fewer parts: no .face
// or .edge file).
#include "fuzz_reader.h"

#include <vector>

namespace IO = CGAL::BODT_3::IO;

namespace {

IO::internal::Texts split(std::string_view b)
{
  std::vector<std::string_view> parts;
  for(std::size_t at; parts.size() < 3 && (at = b.find("\n%%\n")) != std::string_view::npos; b = b.substr(at + 4))
    parts.push_back(b.substr(0, at));
  parts.push_back(b);
  IO::internal::Texts t;
  t.node_file = "fuzz.node";
  t.ele_file = "fuzz.ele";
  t.node = parts[0];
  if(parts.size() > 1) t.ele = parts[1];
  if(parts.size() > 2) { t.face_file = "fuzz.face"; t.face = parts[2]; }
  if(parts.size() > 3) { t.edge_file = "fuzz.edge"; t.edge = parts[3]; }
  return t;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::ostringstream warnings;
  return bodt_fuzz::run(
      data, size, [&](std::string_view b) { return IO::internal::parse_tetgen(split(b), warnings); },
      [&](const CGAL::BODT_3::Tet_mesh& m) {
        std::ostringstream node, ele, face, edge;
        IO::internal::write(node, ele, face, edge, m);
        const std::string text = node.str() + "\n%%\n" + ele.str() + "\n%%\n" + face.str() + "\n%%\n" + edge.str();
        const auto r = IO::internal::parse_tetgen(split(text), warnings);
        bodt_fuzz::require_same(m, r, false, true);
      });
}
