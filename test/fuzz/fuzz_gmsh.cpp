// libFuzzer harness: the Gmsh reader (.msh 2.2 and 4.1, ASCII and binary).
#include "fuzz_reader.h"

namespace IO = CGAL::BODT_3::IO;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  int version = 0;
  bool binary = false;
  std::ostringstream warnings;
  return bodt_fuzz::run(
      data, size, [&](std::string_view b) { return IO::internal::parse_gmsh("fuzz.msh", b, warnings, version, binary); },
      [&](const CGAL::BODT_3::Tet_mesh& m) {
        std::ostringstream out;
        IO::write_gmsh(out, m, version, binary);
        int again = 0;
        bool again_binary = false;
        const auto r = IO::internal::parse_gmsh("again.msh", out.str(), warnings, again, again_binary);
        bodt_fuzz::require(again == version && again_binary == binary, "the variant");
        bodt_fuzz::require_same(m, r, true, false);
      });
}
