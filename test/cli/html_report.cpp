// `bodt smooth --html`: the page is self-contained, its table shows the quality
// of the input and output meshes and the volume of every subdomain, and a
// headless Chromium renders it with both histograms overlaid on one axis: grey
// bars (before) and blue bars (after) over the same degrees, and a single sliver
// below 10 degrees visible as a bar. Its pictures of the mesh draw every boundary
// triangle facing the viewer and every tetrahedron the cut meets, before and
// after, on the demo's mesh too, within a size budget; Chromium renders them.
#include "report/html_report.h"
#include "report/mesh_pictures.h"

#include <CGAL/BODT_3/IO/medit.h>
#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/mesh_quality.h>

#include "test_support.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace fs = std::filesystem;
using namespace bodt_test;
namespace BODT = CGAL::BODT_3;
using BODT::Tet_mesh;
using Point = Tet_mesh::Point;

namespace {

// Deterministic offset in [-0.5, 0.5] per grid point and axis: the same mesh on every machine.
double jitter(int i, int j, int k, int axis)
{
  std::uint32_t h = static_cast<std::uint32_t>(i) * 73856093u ^ static_cast<std::uint32_t>(j) * 19349663u ^
                    static_cast<std::uint32_t>(k) * 83492791u ^ static_cast<std::uint32_t>(axis) * 2654435761u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return static_cast<double>(h % 10001u) / 10000.0 - 0.5;
}

// An n x n x n grid of unit cubes (4 by default), each split into the 6 tetrahedra around its main
// diagonal (a conforming mesh), with the interior grid points moved by up to 0.15
// on each axis so that smoothing has something to improve.
Tet_mesh jittered_grid(int n = 4)
{
  Tet_mesh m = bodt_test::cube_grid(n, [](int, int, int) { return 1; });
  for(int k = 1; k < n; ++k)
    for(int j = 1; j < n; ++j)
      for(int i = 1; i < n; ++i)
        m.points[bodt_test::grid_index(n, i, j, k)] =
            Point(i + 0.3 * jitter(i, j, k, 0), j + 0.3 * jitter(i, j, k, 1), k + 0.3 * jitter(i, j, k, 2));
  return m;
}

// The contents of the <td> cells of the table row whose header starts with `label`.
std::vector<std::string> row_cells(const std::string& html, const std::string& label)
{
  std::vector<std::string> cells;
  const std::size_t start = html.find("<th scope=\"row\">" + label);
  if(start == std::string::npos) return cells;
  const std::size_t end = html.find("</tr>", start);
  for(std::size_t p = html.find("<td>", start); p < end; p = html.find("<td>", p))
  {
    p += 4;
    cells.push_back(html.substr(p, html.find("</td>", p) - p));
  }
  return cells;
}

std::size_t occurrences(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

std::string format(const char* fmt, double x)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

struct Image
{
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;   // row by row, 3 bytes a pixel
  const std::uint8_t* at(int x, int y) const { return &rgb[3 * (static_cast<std::size_t>(y) * width + x)]; }
};

std::uint32_t big_endian(const std::uint8_t* p)
{
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | std::uint32_t(p[3]);
}

// A PNG decoder for what Chromium writes: 8-bit RGB or RGBA, not interlaced.
Image decode_png(const std::string& file)
{
  const std::string data = read_text(file);
  const auto* d = reinterpret_cast<const std::uint8_t*>(data.data());
  const std::uint8_t signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  if(data.size() < 8 || !std::equal(signature, signature + 8, d)) throw std::runtime_error(file + ": not a PNG file");
  Image img;
  int channels = 0;
  std::vector<std::uint8_t> compressed;
  for(std::size_t p = 8; p + 12 <= data.size();)
  {
    const std::uint32_t length = big_endian(d + p);
    const std::string type(data, p + 4, 4);
    const std::uint8_t* body = d + p + 8;
    if(p + 12 + length > data.size()) throw std::runtime_error(file + ": truncated chunk " + type);
    if(type == "IHDR")
    {
      img.width = static_cast<int>(big_endian(body));
      img.height = static_cast<int>(big_endian(body + 4));
      const int depth = body[8], colour_type = body[9], interlace = body[12];
      channels = colour_type == 2 ? 3 : colour_type == 6 ? 4 : 0;
      if(depth != 8 || channels == 0 || interlace != 0)
        throw std::runtime_error(file + ": unsupported PNG (bit depth " + std::to_string(depth) + ", colour type " +
                                 std::to_string(colour_type) + ", interlace " + std::to_string(interlace) + ")");
    }
    else if(type == "IDAT")
      compressed.insert(compressed.end(), body, body + length);
    else if(type == "IEND")
      break;
    p += 12 + length;
  }
  if(channels == 0 || img.width <= 0 || img.height <= 0) throw std::runtime_error(file + ": no image header");
  const std::size_t stride = static_cast<std::size_t>(img.width) * channels;
  std::vector<std::uint8_t> raw(static_cast<std::size_t>(img.height) * (stride + 1));
  uLongf raw_size = raw.size();
  if(uncompress(raw.data(), &raw_size, compressed.data(), compressed.size()) != Z_OK || raw_size != raw.size())
    throw std::runtime_error(file + ": corrupt image data");

  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(img.height) * stride);
  for(int y = 0; y < img.height; ++y)
  {
    const std::uint8_t filter = raw[y * (stride + 1)];
    const std::uint8_t* in = &raw[y * (stride + 1) + 1];
    std::uint8_t* out = &pixels[y * stride];
    const std::uint8_t* up = y > 0 ? out - stride : nullptr;
    for(std::size_t x = 0; x < stride; ++x)
    {
      const int a = x >= static_cast<std::size_t>(channels) ? out[x - channels] : 0;
      const int b = up ? up[x] : 0;
      const int c = up && x >= static_cast<std::size_t>(channels) ? up[x - channels] : 0;
      int predicted = 0;
      switch(filter)
      {
      case 0: break;
      case 1: predicted = a; break;
      case 2: predicted = b; break;
      case 3: predicted = (a + b) / 2; break;
      case 4:
      {
        const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
        predicted = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        break;
      }
      default: throw std::runtime_error(file + ": bad filter type " + std::to_string(filter));
      }
      out[x] = static_cast<std::uint8_t>(in[x] + predicted);
    }
  }
  img.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
  for(std::size_t i = 0; i < static_cast<std::size_t>(img.width) * img.height; ++i)
    std::copy(&pixels[i * channels], &pixels[i * channels] + 3, &img.rgb[3 * i]);
  return img;
}

// Where a colour fills solid areas: pixels whose 5x5 neighbourhood is all that
// colour, so bars and legend swatches count and anti-aliased text does not.
struct Colour_area
{
  std::size_t pixels = 0;
  int left = 1 << 30, top = 1 << 30, right = -1, bottom = -1;
};

Colour_area solid_area(const Image& img, const std::array<int, 3>& colour)
{
  auto matches = [&](int x, int y) {
    const std::uint8_t* p = img.at(x, y);
    for(int c = 0; c < 3; ++c)
      if(std::abs(int(p[c]) - colour[c]) > 2) return false;
    return true;
  };
  std::vector<char> mask(static_cast<std::size_t>(img.width) * img.height);
  for(int y = 0; y < img.height; ++y)
    for(int x = 0; x < img.width; ++x) mask[static_cast<std::size_t>(y) * img.width + x] = matches(x, y);
  Colour_area area;
  for(int y = 2; y + 2 < img.height; ++y)
    for(int x = 2; x + 2 < img.width; ++x)
    {
      bool solid = true;
      for(int dy = -2; dy <= 2 && solid; ++dy)
        for(int dx = -2; dx <= 2 && solid; ++dx)
          solid = mask[static_cast<std::size_t>(y + dy) * img.width + x + dx];
      if(!solid) continue;
      ++area.pixels;
      area.left = std::min(area.left, x);
      area.right = std::max(area.right, x);
      area.top = std::min(area.top, y);
      area.bottom = std::max(area.bottom, y);
    }
  return area;
}

std::string describe(const Colour_area& a)
{
  return std::to_string(a.pixels) + " pixels in x " + std::to_string(a.left) + ".." + std::to_string(a.right) +
         ", y " + std::to_string(a.top) + ".." + std::to_string(a.bottom);
}

// Writes the test mesh, runs `bodt smooth IN -o OUT --html page.html` in `dir`;
// the input name has characters that the page must escape.
struct Smoothing_run
{
  fs::path input, output, page;
  std::string bodt_output;
  int status = -1;
};

Smoothing_run smooth_with_html(const fs::path& dir)
{
  Smoothing_run run;
  run.input = dir / "grid <jittered> & co.mesh";
  run.output = dir / "smoothed.mesh";
  run.page = dir / "page.html";
  fs::remove(run.output);
  fs::remove(run.page);
  BODT::IO::write_medit(run.input.string(), jittered_grid());
  run.status = run_bodt("smooth " + shell_quoted(run.input) + " -o " + shell_quoted(run.output) + " --html " +
                            shell_quoted(run.page),
                        run.bodt_output, dir);
  return run;
}

} // namespace

TEST(HtmlReport, TestMeshIsValid)
{
  const Tet_mesh m = jittered_grid();
  EXPECT_EQ(m.points.size(), 125u);
  EXPECT_EQ(m.tets.size(), 384u);
  for(const auto& t : m.tets)
    ASSERT_EQ(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]), CGAL::POSITIVE);
}

TEST(HtmlReport, EscapesAllGivenText)
{
  const BODT::Quality_report q = BODT::mesh_quality(jittered_grid());
  const std::string html =
      BODT::html_report("<script>alert('x')</script> & \"co\".mesh", q, q, {{"<b>key</b>", "a < b & c > d"}});
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<b>key"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; &quot;co&quot;.mesh"), std::string::npos);
  EXPECT_NE(html.find("&lt;b&gt;key&lt;/b&gt;:</b> a &lt; b &amp; c &gt; d"), std::string::npos);
}

TEST(SmoothHtml, HelpDocumentsTheOption)
{
  std::string output;
  ASSERT_EQ(run_bodt("smooth --help", output, tmp_dir("help")), 0);
  EXPECT_NE(output.find("--html"), std::string::npos) << output;
}

TEST(SmoothHtml, PageIsSelfContainedWithTablesAndOneHistogram)
{
  const fs::path dir = tmp_dir("page");
  const Smoothing_run run = smooth_with_html(dir);
  ASSERT_EQ(run.status, 0) << run.bodt_output;
  ASSERT_TRUE(fs::exists(run.page)) << run.bodt_output;
  const std::string html = read_text(run.page);

  for(const char* external : {"http://", "https://", "<script", "<link", "<img", "<iframe", "src=", "@import", "url("})
    EXPECT_EQ(html.find(external), std::string::npos) << "the page refers to something outside it: " << external;
  // One histogram (before and after belong on one axis), four pictures of the mesh and their legend.
  const std::size_t pictures = occurrences(html, "<svg class=\"mesh-picture");
  EXPECT_EQ(pictures, 4u);
  EXPECT_EQ(occurrences(html, "<svg class=\"legend\""), 1u);
  EXPECT_EQ(occurrences(html, "<svg"), 1 + pictures + 1) << "before and after belong on one axis";
  EXPECT_EQ(occurrences(html, "<figcaption>"), 1 + pictures);
  EXPECT_NE(html.find("log scale"), std::string::npos);
  EXPECT_NE(html.find(std::string("fill=\"") + BODT::report_before_colour + "\""), std::string::npos);
  EXPECT_NE(html.find(std::string("fill=\"") + BODT::report_after_colour + "\""), std::string::npos);
  EXPECT_NE(html.find("dihedral angle (degrees)"), std::string::npos);

  // The title is the input file name, escaped.
  EXPECT_EQ(html.find("<jittered>"), std::string::npos);
  EXPECT_NE(html.find("<h1>" + BODT::html_escape(run.input.string()) + "</h1>"), std::string::npos);

  // The table shows the quality of the input and of the output mesh.
  const BODT::Quality_report before = BODT::mesh_quality(BODT::IO::read_medit(run.input.string()));
  const BODT::Quality_report after = BODT::mesh_quality(BODT::IO::read_medit(run.output.string()));
  EXPECT_GT(after.min_dihedral_deg, before.min_dihedral_deg + 1) << "smoothing changed too little for a test";
  auto expect_row = [&](const std::string& label, const std::string& b, const std::string& a) {
    EXPECT_EQ(row_cells(html, label), (std::vector<std::string>{b, a})) << label;
  };
  expect_row("vertices", "125", "125");
  expect_row("tetrahedra", "384", "384");
  expect_row("min dihedral angle", format("%.2f", before.min_dihedral_deg), format("%.2f", after.min_dihedral_deg));
  expect_row("max dihedral angle", format("%.2f", before.max_dihedral_deg), format("%.2f", after.max_dihedral_deg));
  expect_row("tets with an angle below 10", std::to_string(before.tets_below_small),
             std::to_string(after.tets_below_small));
  expect_row("tets with an angle above 170", std::to_string(before.tets_above_large),
             std::to_string(after.tets_above_large));
  expect_row("mean radius ratio", format("%.4f", before.mean_radius_ratio), format("%.4f", after.mean_radius_ratio));
  expect_row("min radius ratio", format("%.4f", before.min_radius_ratio), format("%.4f", after.min_radius_ratio));
  expect_row("volume", format("%.10g", before.volume), format("%.10g", after.volume));
  expect_row("inverted or flat tets", "0", "0");
  expect_row("bad tets in the interior", std::to_string(before.bad_tets_interior),
             std::to_string(after.bad_tets_interior));
  expect_row("bad tets with all vertices on the boundary", std::to_string(before.bad_tets_all_vertices_on_boundary),
             std::to_string(after.bad_tets_all_vertices_on_boundary));
  // The tails are counted in the page, and every subdomain's volume is shown.
  EXPECT_NE(html.find("below 10&deg;: " + std::to_string(before.tets_below_small) + " before, " +
                      std::to_string(after.tets_below_small) + " after"),
            std::string::npos);
  for(const auto& kv : before.volume_per_subdomain)
    EXPECT_EQ(row_cells(html, std::to_string(kv.first)).size(), 3u) << "subdomain " << kv.first;
  for(const char* item : {"method:</b> bodt", "iterations:", "time:", "moved vertices:", "relative volume change:"})
    EXPECT_NE(html.find(item), std::string::npos) << item;
}

namespace {

// Runs headless Chromium on `page` with a fresh profile and `what` ("--screenshot=..."
// or "--dump-dom"); returns what it printed on stdout.
std::string chromium(const fs::path& page, const fs::path& dir, const std::string& what)
{
  if(std::system("command -v chromium > /dev/null 2>&1") != 0)
    throw std::runtime_error("chromium is not installed; run scripts/setup.sh, which installs it");
  // A fresh profile, so no state of an earlier run or another user is involved.
  std::string profile_template = (fs::temp_directory_path() / "bodt_chromium_XXXXXX").string();
  if(::mkdtemp(profile_template.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  const fs::path profile = profile_template;
  const fs::path out = dir / "chromium_stdout.txt";
  const fs::path log = dir / "chromium_output.txt";
  // Without scrollbars, whose grey would count as the histogram's on a long page.
  const std::string cmd = "timeout 300 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
                          "--disable-background-networking --disable-component-update --disable-sync --hide-scrollbars "
                          "--user-data-dir=" + shell_quoted(profile) + " " + what + " " +
                          shell_quoted("file://" + page.string()) + " > " + shell_quoted(out) + " 2> " + shell_quoted(log);
  const int raw = std::system(cmd.c_str());
  const int status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  std::error_code ignored;
  fs::remove_all(profile, ignored);
  if(status != 0) throw std::runtime_error("chromium failed (" + std::to_string(status) + "):\n" + read_text(log));
  return read_text(out);
}

// A headless Chromium screenshot of `page`, 1280 pixels wide, kept as `name` in `dir`, decoded.
Image screenshot(const fs::path& page, const fs::path& dir, int height = 1600, const std::string& name = "screenshot.png")
{
  const fs::path png = dir / name;
  fs::remove(png);
  chromium(page, dir, "--window-size=1280," + std::to_string(height) + " --screenshot=" + shell_quoted(png));
  if(!fs::exists(png)) throw std::runtime_error("chromium wrote no screenshot:\n" + read_text(dir / "chromium_output.txt"));
  return decode_png(png.string());
}

const std::array<int, 3> grey_rgb = {0x8c, 0x8c, 0x8c};
const std::array<int, 3> blue_rgb = {0x1f, 0x77, 0xb4};
const std::array<int, 3> tail_rgb = {0xfb, 0xe3, 0xe3};

// Solid pixels of `colour` whose x lies in [left, right].
std::size_t solid_pixels_between(const Image& img, const std::array<int, 3>& colour, int left, int right)
{
  Image strip = img;
  for(int y = 0; y < img.height; ++y)
    for(int x = 0; x < img.width; ++x)
      if(x < left || x > right) std::fill_n(&strip.rgb[3 * (static_cast<std::size_t>(y) * img.width + x)], 3, 255);
  return solid_area(strip, colour).pixels;
}

} // namespace

TEST(SmoothHtml, ChromiumScreenshotShowsBothHistogramsOnOneAxis)
{
  const fs::path dir = tmp_dir("screenshot");
  const Smoothing_run run = smooth_with_html(dir);
  ASSERT_EQ(run.status, 0) << run.bodt_output;
  const Image img = screenshot(run.page, dir);
  EXPECT_EQ(img.width, 1280);
  EXPECT_EQ(img.height, 1600);
  const Colour_area grey = solid_area(img, grey_rgb);
  const Colour_area blue = solid_area(img, blue_rgb);
  SCOPED_TRACE("before (grey): " + describe(grey) + "; after (blue): " + describe(blue) + "; " +
               (dir / "screenshot.png").string());
  EXPECT_GT(grey.pixels, 500u);
  EXPECT_GT(blue.pixels, 500u);
  // Each colour spans a histogram, not just a legend swatch ...
  EXPECT_GT(grey.right - grey.left, 100);
  EXPECT_GT(grey.bottom - grey.top, 50);
  EXPECT_GT(blue.right - blue.left, 100);
  EXPECT_GT(blue.bottom - blue.top, 50);
  // ... and both lie over the same degrees and stand on the same baseline: one axis.
  EXPECT_LT(grey.left, blue.right);
  EXPECT_LT(blue.left, grey.right);
  EXPECT_LE(std::abs(grey.bottom - blue.bottom), 3);
}

// One sliver among hundreds of good tetrahedra shows as a bar in the shaded tail
// below 10 degrees, where the input had none.
TEST(SmoothHtml, ChromiumScreenshotShowsASingleSliver)
{
  const fs::path dir = tmp_dir("sliver");
  Tet_mesh good = jittered_grid();
  const BODT::Quality_report before = BODT::mesh_quality(good);
  ASSERT_EQ(before.tets_below_small, 0u);
  Tet_mesh with_sliver = good;
  const int base = static_cast<int>(with_sliver.points.size());
  for(const Point& p : {Point(10, 0, 0), Point(11, 0, 0), Point(10, 1, 0), Point(10.4, 0.4, 0.03)})
  {
    with_sliver.points.push_back(p);
    with_sliver.vertex_refs.push_back(0);
  }
  with_sliver.tets.push_back({base, base + 1, base + 2, base + 3});
  with_sliver.tet_labels.push_back(1);
  const BODT::Quality_report after = BODT::mesh_quality(with_sliver);
  ASSERT_EQ(after.inverted_tets, 0u);
  ASSERT_EQ(after.tets_below_small, 1u);
  const fs::path page = dir / "sliver.html";
  std::ofstream(page) << BODT::html_report("one sliver", before, after, {});
  const Image img = screenshot(page, dir);

  const Colour_area tail = solid_area(img, tail_rgb);   // both shaded tails
  SCOPED_TRACE("tails: " + describe(tail) + "; " + (dir / "screenshot.png").string());
  ASSERT_GT(tail.pixels, 1000u);
  // The left tail: the shaded run of pixels that starts at the tails' left edge,
  // on a row near the top of the plot, where no bar of a tail reaches.
  auto is_tail = [&](int x, int y) {
    const std::uint8_t* p = img.at(x, y);
    for(int c = 0; c < 3; ++c)
      if(std::abs(int(p[c]) - tail_rgb[c]) > 2) return false;
    return true;
  };
  int left_tail_right = tail.left;
  while(left_tail_right + 1 < img.width && is_tail(left_tail_right + 1, tail.top + 2)) ++left_tail_right;
  ASSERT_GT(left_tail_right - tail.left, 20) << "the tail below 10 degrees is too narrow to read";
  EXPECT_GT(solid_pixels_between(img, blue_rgb, tail.left, left_tail_right), 25u)
      << "the single sliver does not show below 10 degrees";
  EXPECT_EQ(solid_pixels_between(img, grey_rgb, tail.left, left_tail_right), 0u)
      << "the input had no angle below 10 degrees";
}

namespace {

using Vec3 = std::array<double, 3>;

Vec3 vec3(const Point& p) { return {p.x(), p.y(), p.z()}; }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

// One picture of the page: the attributes of its <svg> tag and its cells group.
struct Svg_picture
{
  std::map<std::string, std::string> attributes;
  std::string cells;   // the content of <g class="cells">
  std::size_t number(const std::string& name) const { return std::stoul(attributes.at(name)); }
  std::vector<double> numbers(const std::string& name) const
  {
    std::istringstream in(attributes.at(name));
    std::vector<double> v;
    for(double x; in >> x;) v.push_back(x);
    return v;
  }
  // The filled paths of the cells group: one per cell (feature edges have a class, no fill).
  std::size_t filled_paths() const { return occurrences(cells, "<path d="); }
  std::set<std::string> fills() const
  {
    std::set<std::string> out;
    static const std::regex fill("fill=\"(#[0-9a-f]{6})\"");
    for(std::sregex_iterator it(cells.begin(), cells.end(), fill), end; it != end; ++it) out.insert((*it)[1]);
    return out;
  }
};

// The mesh pictures of a page, or of Chromium's serialization of its DOM, in page order.
std::vector<Svg_picture> pictures_of(const std::string& html)
{
  std::vector<Svg_picture> out;
  static const std::regex attribute("([a-zA-Z-]+)=\"([^\"]*)\"");
  const std::string open = "<svg class=\"mesh-picture";
  for(std::size_t p = html.find(open); p != std::string::npos; p = html.find(open, p + 1))
  {
    Svg_picture pic;
    const std::string tag = html.substr(p, html.find('>', p) - p);
    for(std::sregex_iterator it(tag.begin(), tag.end(), attribute), end; it != end; ++it)
      pic.attributes[(*it)[1]] = (*it)[2];
    const std::size_t cells = html.find("<g class=\"cells\">", p);
    pic.cells = html.substr(cells, html.find("</g>", cells) - cells);
    out.push_back(pic);
  }
  return out;
}

// The boundary faces of the tetrahedra in the mesh (labelled other than 0, unless
// all are), from a map of sorted faces; each with its outward normal.
struct Boundary_face
{
  std::array<int, 3> v;
  Vec3 normal;
};

std::vector<Boundary_face> boundary_faces(const Tet_mesh& m)
{
  const bool all_zero = m.all_labels_zero();
  std::map<std::array<int, 3>, std::vector<std::pair<std::array<int, 3>, int>>> faces;
  for(std::size_t t = 0; t < m.tets.size(); ++t)
  {
    if(!all_zero && m.tet_labels[t] == 0) continue;
    for(int i = 0; i < 4; ++i)
    {
      std::array<int, 3> f;
      for(int j = 0, n = 0; j < 4; ++j)
        if(j != i) f[n++] = m.tets[t][j];
      std::array<int, 3> key = f;
      std::sort(key.begin(), key.end());
      faces[key].emplace_back(f, m.tets[t][i]);
    }
  }
  std::vector<Boundary_face> out;
  for(const auto& kv : faces)
  {
    if(kv.second.size() != 1) continue;
    const auto& [f, opposite] = kv.second.front();
    const Vec3 a = vec3(m.points[f[0]]);
    Vec3 n = cross(sub(vec3(m.points[f[1]]), a), sub(vec3(m.points[f[2]]), a));
    if(dot(n, sub(vec3(m.points[opposite]), a)) > 0) n = {-n[0], -n[1], -n[2]};
    out.push_back({f, n});
  }
  return out;
}

std::size_t faces_towards(const std::vector<Boundary_face>& faces, const Vec3& toward)
{
  return static_cast<std::size_t>(
      std::count_if(faces.begin(), faces.end(), [&](const Boundary_face& f) { return dot(f.normal, toward) > 0; }));
}

// Edges between two boundary faces whose normals differ by more than `degrees`,
// with a face on them turned towards the viewer.
std::size_t sharp_edges_towards(const std::vector<Boundary_face>& faces, const Vec3& toward, double degrees)
{
  std::map<std::pair<int, int>, std::vector<std::size_t>> around;
  for(std::size_t k = 0; k < faces.size(); ++k)
    for(int i = 0; i < 3; ++i)
    {
      const int a = faces[k].v[i], b = faces[k].v[(i + 1) % 3];
      around[{std::min(a, b), std::max(a, b)}].push_back(k);
    }
  std::size_t n = 0;
  for(const auto& kv : around)
  {
    if(kv.second.size() != 2) continue;
    const Vec3& s = faces[kv.second[0]].normal;
    const Vec3& t = faces[kv.second[1]].normal;
    const bool seen = dot(s, toward) > 0 || dot(t, toward) > 0;
    if(seen && std::acos(std::max(-1.0, std::min(1.0, dot(s, t) / (norm(s) * norm(t))))) * 180 / CGAL_PI > degrees) ++n;
  }
  return n;
}

// The tetrahedra a plane cuts: those it crosses (vertices strictly on both sides),
// and those with a face on it and the fourth vertex below (each face drawn once).
std::size_t cells_cut(const Tet_mesh& m, const Vec3& point, const Vec3& normal)
{
  const bool all_zero = m.all_labels_zero();
  std::size_t n = 0;
  for(std::size_t t = 0; t < m.tets.size(); ++t)
  {
    if(!all_zero && m.tet_labels[t] == 0) continue;
    int below = 0, above = 0;
    for(int v : m.tets[t])
    {
      const double d = dot(sub(vec3(m.points[v]), point), normal);
      below += d < 0;
      above += d > 0;
    }
    if((below > 0 && above > 0) || (below == 1 && above == 0)) ++n;
  }
  return n;
}

// The centroid of the tetrahedron with the smallest dihedral angle (the first of equals).
Vec3 worst_centroid(const Tet_mesh& m)
{
  const bool all_zero = m.all_labels_zero();
  double worst = 1e9;
  Vec3 at{0, 0, 0};
  for(std::size_t t = 0; t < m.tets.size(); ++t)
  {
    if(!all_zero && m.tet_labels[t] == 0) continue;
    const auto& c = m.tets[t];
    const auto a = BODT::internal::dihedral_angles(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]);
    const double lo = *std::min_element(a.begin(), a.end());
    if(lo >= worst) continue;
    worst = lo;
    at = {0, 0, 0};
    for(int v : c)
      for(int k = 0; k < 3; ++k) at[k] += m.points[v][k] / 4;
  }
  return at;
}

// The page's four pictures draw what the meshes hold: every boundary triangle
// facing the viewer, every tetrahedron the plane cuts (through the input's worst
// one unless `plane` is given), before and after; and ring the worst.
void expect_pictures_of(const std::string& html, const Tet_mesh& input, const Tet_mesh& output,
                        const std::optional<std::array<double, 6>>& plane = std::nullopt)
{
  const std::vector<Svg_picture> pictures = pictures_of(html);
  ASSERT_EQ(pictures.size(), 4u);
  const char* kinds[4][2] = {{"surface", "before"}, {"surface", "after"}, {"cut", "before"}, {"cut", "after"}};
  for(int i = 0; i < 4; ++i)
  {
    SCOPED_TRACE(std::string(kinds[i][0]) + " " + kinds[i][1]);
    const Svg_picture& p = pictures[i];
    EXPECT_EQ(p.attributes.at("data-kind"), kinds[i][0]);
    EXPECT_EQ(p.attributes.at("data-stage"), kinds[i][1]);
    EXPECT_EQ(p.filled_paths(), p.number("data-cells"));
    EXPECT_EQ(p.number("data-marked"), std::min<std::size_t>(10, p.number("data-source-cells")));
    const Tet_mesh& m = i % 2 == 0 ? input : output;
    if(i < 2)
    {
      const std::vector<double> v = p.numbers("data-view");
      ASSERT_EQ(v.size(), 3u);
      const Vec3 toward{v[0], v[1], v[2]};
      EXPECT_NEAR(norm(toward), 1.0, 1e-12);
      EXPECT_EQ(p.number("data-source-cells"), faces_towards(boundary_faces(m), toward));
      // Without feature information, edges turning by more than the default feature angle are drawn.
      EXPECT_EQ(p.number("data-features"), sharp_edges_towards(boundary_faces(m), toward, 25.21));
    }
    else
    {
      const std::vector<double> c = p.numbers("data-plane");
      ASSERT_EQ(c.size(), 6u);
      const Vec3 point{c[0], c[1], c[2]}, normal{c[3], c[4], c[5]};
      if(plane)
        for(int k = 0; k < 6; ++k) EXPECT_EQ(c[k], (*plane)[k]) << k;
      else
      {
        const Vec3 worst = worst_centroid(input);
        for(int k = 0; k < 3; ++k) EXPECT_NEAR(point[k], worst[k], 1e-12 * (1 + std::abs(worst[k]))) << k;
        const std::vector<double> v = pictures[0].numbers("data-view");
        for(int k = 0; k < 3; ++k) EXPECT_EQ(normal[k], v[k]) << "the default cut faces the surface's viewer";
      }
      EXPECT_EQ(p.number("data-source-cells"), cells_cut(m, point, normal));
      EXPECT_GT(p.number("data-features"), 0u) << "the boundary crosses every cut";
    }
    if(p.number("data-cells") == p.number("data-source-cells"))
    {
      EXPECT_EQ(p.attributes.at("class"), "mesh-picture") << "not simplified";
    }
  }
}

} // namespace

TEST(SmoothHtml, PicturesDrawEveryCellOfTheSurfaceAndTheCut)
{
  const fs::path dir = tmp_dir("page");
  const Smoothing_run run = smooth_with_html(dir);
  ASSERT_EQ(run.status, 0) << run.bodt_output;
  const std::string html = read_text(run.page);
  const Tet_mesh input = BODT::IO::read_medit(run.input.string()), output = BODT::IO::read_medit(run.output.string());
  expect_pictures_of(html, input, output);
  // The grid is a box seen from +x, -y, +z: three sides of 4 x 4 squares of two
  // triangles face the viewer, and 9 of its 12 edges (of 4 segments) touch them.
  const std::vector<Svg_picture> p = pictures_of(html);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[0].number("data-cells"), 96u);
  EXPECT_EQ(p[0].number("data-features"), 36u);
  // The input has worse cells than the output: its cut shows worse colours.
  EXPECT_NE(p[2].fills(), p[3].fills());
  EXPECT_NE(html.find(BODT::html_escape("Before: 96 of the 192 boundary triangles face the viewer")),
            std::string::npos);
}

// A plane along grid vertices: faces on the plane are drawn once, cells that only
// touch it are not.
TEST(SmoothHtml, CutPlaneChosenByTheUser)
{
  const fs::path dir = tmp_dir();
  const Smoothing_run run = smooth_with_html(dir);
  ASSERT_EQ(run.status, 0) << run.bodt_output;
  std::string output;
  const fs::path page = dir / "cut.html";
  ASSERT_EQ(run_bodt("smooth " + shell_quoted(run.input) + " -o " + shell_quoted(dir / "cut.mesh") + " --html " +
                         shell_quoted(page) + " --cut z=2 --quiet",
                     output, dir),
            0)
      << output;
  const std::string html = read_text(page);
  expect_pictures_of(html, BODT::IO::read_medit(run.input.string()), BODT::IO::read_medit((dir / "cut.mesh").string()),
                     std::array<double, 6>{0, 0, 2, 0, 0, 1});
  EXPECT_NE(html.find("given by --cut"), std::string::npos);
}

TEST(MeshPictures, CutPlanesAreReadOrRefusedWithTheReason)
{
  const bodt_report::Cut_plane y = bodt_report::parse_cut_plane(" Y = -1.5 ");
  EXPECT_EQ(y.point, (std::array<double, 3>{0, -1.5, 0}));
  EXPECT_EQ(y.normal, (std::array<double, 3>{0, 1, 0}));
  const bodt_report::Cut_plane general = bodt_report::parse_cut_plane("1,2,3,0,0.5,-1");
  EXPECT_EQ(general.point, (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(general.normal, (std::array<double, 3>{0, 0.5, -1}));
  for(const char* bad : {"", "z", "w=1", "z=", "z=1x", "1,2,3", "1,2,3,4,5,6,7", "1,2,3,a,5,6", "z=nan", "x=inf"})
    EXPECT_THROW(bodt_report::parse_cut_plane(bad), std::invalid_argument) << bad;
  try
  {
    bodt_report::parse_cut_plane("1,2,3,0,0,0");
    ADD_FAILURE() << "a zero normal was accepted";
  }
  catch(const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("must not be zero"), std::string::npos) << e.what();
  }
  const Tet_mesh grid = jittered_grid();
  EXPECT_TRUE(bodt_report::plane_meets_mesh(bodt_report::parse_cut_plane("x=0"), grid));
  EXPECT_TRUE(bodt_report::plane_meets_mesh(bodt_report::parse_cut_plane("0,0,0,1,1,1"), grid));
  EXPECT_FALSE(bodt_report::plane_meets_mesh(bodt_report::parse_cut_plane("x=-0.01"), grid));
  EXPECT_FALSE(bodt_report::plane_meets_mesh(bodt_report::parse_cut_plane("-1,0,0,1,1,1"), grid));
}

// Beyond the budget of cells, vertices are merged: the pictures stay within it,
// say so, and the cut still shows the colour of the worst cell it meets.
TEST(MeshPictures, LargeMeshesAreSimplifiedWithinTheBudget)
{
  const int n = 24;
  const Tet_mesh m = jittered_grid(n);
  const bodt_report::Picture_options options;
  const std::string html = bodt_report::mesh_pictures_html(m, m, options);
  const std::vector<Svg_picture> p = pictures_of(html);
  ASSERT_EQ(p.size(), 4u);
  for(const Svg_picture& picture : p)
  {
    EXPECT_LE(picture.number("data-cells"), options.max_cells);
    EXPECT_GT(picture.number("data-cells"), options.max_cells / 4) << "simplified too far";
    EXPECT_EQ(picture.filled_paths(), picture.number("data-cells"));
  }
  EXPECT_EQ(p[0].number("data-source-cells"), 3u * n * n * 2);
  EXPECT_EQ(p[0].attributes.at("class"), "mesh-picture dense");
  EXPECT_NE(html.find("<b>Simplified</b>"), std::string::npos);
  EXPECT_LT(html.size(), 400000u) << "the page must stay small";

  // The worst cell the default cut meets is the input's worst.
  double worst = 180;
  for(const auto& c : m.tets)
    worst = std::min(worst, BODT::internal::min_max_dihedral_angle(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]).first);
  bodt_report::Picture_options small = options;
  small.max_cells = 300;
  const std::vector<Svg_picture> q = pictures_of(bodt_report::mesh_pictures_html(m, m, small));
  ASSERT_EQ(q.size(), 4u);
  EXPECT_GT(q[2].number("data-source-cells"), small.max_cells);
  EXPECT_LE(q[2].number("data-cells"), small.max_cells);
  EXPECT_EQ(q[2].fills().count(bodt_report::quality_colour(worst)), 1u) << "the worst colour was merged away";
}

namespace {

// Solid areas of the two picture backgrounds: the pictures before on the left and
// after on the right, two rows each, and in each column pixels of `colours`.
void expect_rendered_pictures(const Image& img, const std::set<std::string>& cut_colours)
{
  auto rgb = [](const std::string& hex) {
    return std::array<int, 3>{std::stoi(hex.substr(1, 2), nullptr, 16), std::stoi(hex.substr(3, 2), nullptr, 16),
                              std::stoi(hex.substr(5, 2), nullptr, 16)};
  };
  const Colour_area before = solid_area(img, rgb(bodt_report::picture_before_background));
  const Colour_area after = solid_area(img, rgb(bodt_report::picture_after_background));
  SCOPED_TRACE("before: " + describe(before) + "; after: " + describe(after));
  EXPECT_GT(before.pixels, 50000u);
  EXPECT_GT(after.pixels, 50000u);
  EXPECT_LT(before.right, after.left) << "before on the left, after on the right";
  EXPECT_GT(before.bottom - before.top, 700) << "two rows of pictures";
  // The cut's cells are drawn in their colours, unshaded.
  std::size_t coloured = 0;
  for(const std::string& c : cut_colours)
    coloured += solid_pixels_between(img, rgb(c), before.left, before.right);
  EXPECT_GT(coloured, 5000u);
  // The rings are thin: their pixels of exactly the ring's colour.
  const std::array<int, 3> ring = rgb(bodt_report::worst_ring_colour);
  std::size_t ring_pixels = 0;
  for(int y = 0; y < img.height; ++y)
    for(int x = before.left; x <= after.right; ++x)
      ring_pixels += std::equal(ring.begin(), ring.end(), img.at(x, y), [](int a, std::uint8_t b) { return a == b; });
  EXPECT_GT(ring_pixels, 200u) << "the worst tetrahedra are not ringed";
}

} // namespace

// Chromium reads the page into the same pictures (its DOM has every cell), and
// draws them: before left, after right, the cut in the colours of its cells.
TEST(SmoothHtml, ChromiumRendersThePictures)
{
  const fs::path dir = tmp_dir("screenshot");
  const Smoothing_run run = smooth_with_html(dir);
  ASSERT_EQ(run.status, 0) << run.bodt_output;
  const std::vector<Svg_picture> in_file = pictures_of(read_text(run.page));
  const std::vector<Svg_picture> in_dom = pictures_of(chromium(run.page, dir, "--dump-dom"));
  ASSERT_EQ(in_dom.size(), 4u);
  for(std::size_t i = 0; i < in_dom.size(); ++i)
  {
    EXPECT_EQ(in_dom[i].filled_paths(), in_file[i].number("data-cells")) << i;
    EXPECT_EQ(in_dom[i].attributes, in_file[i].attributes) << i;
  }
  const Image img = screenshot(run.page, dir, 3000, "pictures.png");
  SCOPED_TRACE((dir / "pictures.png").string());
  expect_rendered_pictures(img, in_file[2].fills());
}

// The demo's page (scripts/demo.sh: CGAL's sphere.mesh, unpacked by setup.sh):
// small, its pictures draw the meshes, Chromium renders them; the screenshot is
// kept in the build folder.
TEST(SmoothHtml, DemoPageShowsTheMeshAndStaysSmall)
{
  const fs::path sphere = fs::path(BODT_DATA_DIR) / "sphere.mesh";
  if(!fs::exists(sphere)) GTEST_SKIP() << sphere << " is missing: scripts/setup.sh unpacks it";
  const fs::path dir = tmp_dir();
  std::string output;
  ASSERT_EQ(run_bodt("smooth " + shell_quoted(sphere) + " -o " + shell_quoted(dir / "sphere-bodt.mesh") +
                         " --report " + shell_quoted(dir / "sphere-bodt.json") + " --html " +
                         shell_quoted(dir / "sphere-bodt.html") + " --quiet",
                     output, dir),
            0)
      << output;
  const std::string html = read_text(dir / "sphere-bodt.html");
  EXPECT_LT(html.size(), 300000u) << "the demo's page must stay a few hundred KB at most";
  expect_pictures_of(html, BODT::IO::read_medit(sphere.string()),
                     BODT::IO::read_medit((dir / "sphere-bodt.mesh").string()));
  const Image img = screenshot(dir / "sphere-bodt.html", dir, 3000, "demo_page.png");
  SCOPED_TRACE((dir / "demo_page.png").string());
  expect_rendered_pictures(img, pictures_of(html)[2].fills());
}
