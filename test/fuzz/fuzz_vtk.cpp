// libFuzzer harness: the legacy VTK reader (.vtk 2.0 to 5.1, ASCII and binary).
#include "fuzz_reader.h"

namespace IO = CGAL::BODT_3::IO;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  int version = 0;
  bool binary = false;
  std::ostringstream warnings;
  return bodt_fuzz::run(
      data, size,
      [&](std::string_view b) { return IO::internal::parse_legacy("fuzz.vtk", b, warnings, version, binary); },
      [&](const CGAL::BODT_3::Tet_mesh& m) {
        std::ostringstream out;
        const int written = version == 51 ? 51 : 42;
        IO::write_vtk(out, m, binary, written);
        int again = 0;
        bool again_binary = false;
        const auto r = IO::internal::parse_legacy("again.vtk", out.str(), warnings, again, again_binary);
        bodt_fuzz::require(again == written && again_binary == binary, "the variant");
        bodt_fuzz::require_same(m, r, true, true);
      });
}
