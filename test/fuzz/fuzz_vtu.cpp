// libFuzzer harness: the VTK XML reader (.vtu: ASCII, base64, appended, zlib).
#include "fuzz_reader.h"

namespace IO = CGAL::BODT_3::IO;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  bool binary = false;
  std::ostringstream warnings;
  return bodt_fuzz::run(
      data, size, [&](std::string_view b) { return IO::internal::parse_vtu("fuzz.vtu", b, warnings, binary); },
      [&](const CGAL::BODT_3::Tet_mesh& m) {
        std::ostringstream out;
        IO::write_vtu(out, m, binary);
        bool again = false;
        const auto r = IO::internal::parse_vtu("again.vtu", out.str(), warnings, again);
        bodt_fuzz::require(again == binary, "the encoding");
        bodt_fuzz::require_same(m, r, true, true);
      });
}
