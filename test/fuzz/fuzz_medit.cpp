// libFuzzer harness: the ASCII Medit reader (.mesh).
#include "fuzz_reader.h"

namespace IO = CGAL::BODT_3::IO;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  int version = 0;
  std::ostringstream warnings;
  return bodt_fuzz::run(
      data, size, [&](std::string_view b) { return IO::internal::parse_medit("fuzz.mesh", b, warnings, version); },
      [&](const CGAL::BODT_3::Tet_mesh& m) {
        std::ostringstream out;
        IO::write_medit(out, m, version);
        int again = 0;
        const auto r = IO::internal::parse_medit("again.mesh", out.str(), warnings, again);
        bodt_fuzz::require(again == version, "the version");
        bodt_fuzz::require_same(m, r, true, true);
        bodt_fuzz::require(m.ridges == r.ridges && m.required_vertices == r.required_vertices, "ridges or required vertices");
      });
}
