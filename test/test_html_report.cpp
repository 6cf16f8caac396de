// `bodt smooth --html`: the page is self-contained, its table shows the quality
// of the input and output meshes and the volume of every subdomain, and a
// headless Chromium renders it with both histograms overlaid on one axis: grey
// bars (before) and blue bars (after) over the same degrees, and a single sliver
// below 10 degrees visible as a bar.
#include "report/html_report.h"

#include <CGAL/BODT_3/IO/medit.h>
#include <CGAL/BODT_3/Tet_mesh.h>
#include <CGAL/BODT_3/mesh_quality.h>

#include "test_support.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
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

// A 4x4x4 grid of unit cubes, each split into the 6 tetrahedra around its main
// diagonal (a conforming mesh), with the interior grid points moved by up to 0.15
// on each axis so that smoothing has something to improve.
Tet_mesh jittered_grid()
{
  const int n = 4;
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
  EXPECT_EQ(occurrences(html, "<svg"), 1u) << "before and after belong on one axis";
  EXPECT_EQ(occurrences(html, "<figcaption>"), 1u);
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

// A headless Chromium screenshot of `page`, 1280x1600, decoded.
Image screenshot(const fs::path& page, const fs::path& dir)
{
  if(std::system("command -v chromium > /dev/null 2>&1") != 0)
    throw std::runtime_error("chromium is not installed; run scripts/setup.sh, which installs it");
  // A fresh profile, so no state of an earlier run or another user is involved.
  std::string profile_template = (fs::temp_directory_path() / "bodt_chromium_XXXXXX").string();
  if(::mkdtemp(profile_template.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  const fs::path profile = profile_template;
  const fs::path png = dir / "screenshot.png";
  const fs::path log = dir / "chromium_output.txt";
  fs::remove(png);
  const std::string cmd = "timeout 300 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
                          "--disable-background-networking --disable-component-update --disable-sync "
                          "--user-data-dir=" + shell_quoted(profile) + " --window-size=1280,1600 --screenshot=" +
                          shell_quoted(png) + " " + shell_quoted("file://" + page.string()) + " > " + shell_quoted(log) + " 2>&1";
  const int raw = std::system(cmd.c_str());
  const int status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  std::error_code ignored;
  fs::remove_all(profile, ignored);
  if(status != 0 || !fs::exists(png)) throw std::runtime_error("chromium wrote no screenshot:\n" + read_text(log));
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
