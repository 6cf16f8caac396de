// The command-line tool's behaviour: --version, a silent --quiet, output paths
// refused before any work, reports that appear with the mesh, valid JSON whatever
// the paths, --json on standard output, --format, --iterations 0, the feature and
// corner angles, the wording of `quality` and `compare`, and the progress display.
#include "cli/feature_angles.h"
#include "cli/progress.h"

#include <CGAL/BODT_3/IO/medit.h>
#include <CGAL/BODT_3/internal/Classification/Tensor_voting.h>
#include <CGAL/BODT_3/Tet_mesh.h>

#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace bodt_test;
namespace BODT = CGAL::BODT_3;
using Point = BODT::Tet_mesh::Point;

namespace {

// A 3x3x3 grid of cubes in two subdomains, interior points moved so that smoothing has work.
BODT::Tet_mesh test_mesh()
{
  const int n = 3;
  BODT::Tet_mesh m = cube_grid(n, [](int i, int, int) { return i < 1 ? 2 : 1; });
  for(int k = 1; k < n; ++k)
    for(int j = 1; j < n; ++j)
      for(int i = 1; i < n; ++i)
        m.points[grid_index(n, i, j, k)] = Point(i + 0.13 * ((i + 2 * j) % 3 - 1), j + 0.11 * ((j + k) % 3 - 1),
                                                 k + 0.12 * ((i + k) % 3 - 1));
  return m;
}

fs::path write_test_mesh(const fs::path& dir, const std::string& name = "in.mesh")
{
  const fs::path p = dir / name;
  BODT::IO::write_medit(p.string(), test_mesh());
  return p;
}

std::string q(const fs::path& p) { return shell_quoted(p); }

} // namespace

TEST(Cli, VersionAndHelp)
{
  std::string out;
  ASSERT_EQ(run_bodt("--version", out), 0);
  EXPECT_EQ(out.rfind(std::string("bodt ") + BODT_VERSION, 0), 0u) << out;
  ASSERT_EQ(run_bodt("smooth --help", out), 0);
  for(const char* option : {"--method", "--no-flips", "--no-insertion", "--max-insertions", "--format", "--quiet",
                            "--report", "--html", "--iterations", "--convergence", "--feature-angle", "--corner-angle",
                            "--cut", "--json", "--max-boundary-distance", "--contraction", "--max-removals", "--worst-cell-phase"})
    EXPECT_NE(out.find(option), std::string::npos) << option;
  EXPECT_EQ(run_bodt("", out), 2);
  EXPECT_EQ(run_bodt("smooth", out), 2);
  EXPECT_EQ(run_bodt("smooth in.mesh -o out.mesh --method simplex", out), 2);
  EXPECT_EQ(run_bodt("smooth in.mesh -o out.mesh --max-boundary-distance -0.001", out), 2);
}

TEST(Cli, QuietPrintsNothing)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir);
  std::string out;
  ASSERT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out.mesh") + " --quiet", out, dir), 0);
  EXPECT_EQ(out, "");
  EXPECT_TRUE(fs::exists(dir / "out.mesh"));
  ASSERT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out2.mesh"), out, dir), 0);
  EXPECT_NE(out.find("min dihedral"), std::string::npos) << out;
  EXPECT_NE(out.find("all vertices on boundary"), std::string::npos) << out;
  EXPECT_NE(out.find("boundary and interfaces moved by"), std::string::npos) << out;
}

// Unusable output paths end the run before the mesh is even read, with the
// option and path in the message, exit status 2, and nothing written.
TEST(Cli, OutputPathsAreRefusedBeforeAnyWork)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir);
  const std::string input_text = read_text(in);
  struct Case
  {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      {"-o " + q(dir / "missing" / "out.mesh"), "does not exist"},
      {"-o " + q(dir / "out.mesh") + " --report " + q(dir / "out.mesh"), "--report"},
      {"-o " + q(dir / "out.mesh") + " --html " + q(dir / "r.json") + " --report " + q(dir / "r.json"), "same file"},
      {"-o " + q(in), "the input"},
      {"-o " + q(dir / "." / "in.mesh"), "the input"},
      {"-o " + q(dir), "folder"},
      {"-o " + q(dir / "out.mesh") + " --report " + q(dir / "missing" / "r.json"), "--report"},
      {"-o " + q(dir / "out.xyz"), "cannot tell the output format"},
      {"-o " + q(dir / "out.mesh") + " --format vtu", "contradicts"},
  };
  for(const Case& c : cases)
  {
    std::string out;
    EXPECT_EQ(run_bodt("smooth " + q(in) + " " + c.args, out, dir), 2) << c.args << "\n" << out;
    EXPECT_NE(out.find(c.message), std::string::npos) << c.args << "\n" << out;
    EXPECT_EQ(out.find("interior,"), std::string::npos) << "the mesh was read and classified: " << out;
    EXPECT_FALSE(fs::exists(dir / "out.mesh")) << c.args;
    EXPECT_FALSE(fs::exists(dir / "r.json")) << c.args;
  }
  EXPECT_EQ(read_text(in), input_text);
  // No temporary file is left behind either.
  for(const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
}

// A failed run writes nothing: here the input is refused after the paths were checked.
TEST(Cli, FailedRunWritesNothing)
{
  const fs::path dir = tmp_dir();
  const fs::path in = dir / "broken.mesh";
  std::ofstream(in) << "MeshVersionFormatted 1\nDimension 3\nVertices\n2\n0 0 0 0\n";
  std::string out;
  EXPECT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out.mesh") + " --report " + q(dir / "r.json") +
                         " --html " + q(dir / "r.html"),
                     out, dir),
            1)
      << out;
  EXPECT_NE(out.find("broken.mesh"), std::string::npos) << out;
  for(const char* f : {"out.mesh", "r.json", "r.html"}) EXPECT_FALSE(fs::exists(dir / f)) << f;
  // A folder as input is named in the message.
  fs::create_directories(dir / "folder.mesh");
  EXPECT_EQ(run_bodt("smooth " + q(dir / "folder.mesh") + " -o " + q(dir / "out.mesh"), out, dir), 1);
  EXPECT_NE(out.find("folder.mesh: is a directory"), std::string::npos) << out;
  EXPECT_EQ(run_bodt("quality " + q(dir / "folder.mesh"), out, dir), 1);
  EXPECT_NE(out.find("folder.mesh: is a directory"), std::string::npos) << out;
}

// Paths with a quote and a backslash give valid JSON, which holds everything the
// run knows: options, result totals, one record per sweep, quality before/after,
// the time per phase.
TEST(Cli, ReportIsValidJsonWithEverything)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir, "odd \"name\" \\ here.mesh");
  const fs::path report = dir / "r \"1\".json";
  std::string out;
  ASSERT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out.mesh") + " --report " + q(report) +
                         " --iterations 5 --no-insertion --max-insertions 7 --max-min-threshold 0.2 --largest-angle-threshold 125"
                         " --max-boundary-distance 0.002 --contraction --max-removals 3 --quiet",
                     out, dir),
            0)
      << out;
  const nlohmann::json j = nlohmann::json::parse(read_text(report));
  EXPECT_EQ(j.at("input"), in.string());
  EXPECT_EQ(j.at("output_format"), "mesh");
  EXPECT_EQ(j.at("options").at("max_iteration_number"), 5);
  EXPECT_EQ(j.at("options").at("vertex_insertion"), false);
  EXPECT_EQ(j.at("options").at("topology_optimization"), true);
  EXPECT_EQ(j.at("options").at("max_vertex_insertions"), 7);
  EXPECT_EQ(j.at("options").at("max_min_threshold"), 0.2);
  EXPECT_EQ(j.at("options").at("max_boundary_distance"), 0.002);
  EXPECT_EQ(j.at("options").at("edge_contraction"), true);
  EXPECT_EQ(j.at("options").at("max_vertex_removals"), 3);
  EXPECT_LE(j.at("result").at("contraction").at("contractions").get<std::size_t>(), 3u);
  EXPECT_GE(j.at("boundary_distance").get<double>(), 0.0);
  EXPECT_LE(j.at("boundary_distance").get<double>(), 1e-2);
  EXPECT_EQ(j.at("options").at("method"), "bodt");
  const nlohmann::json& r = j.at("result");
  EXPECT_EQ(j.at("options").at("largest_angle_phase"), true);
  EXPECT_EQ(j.at("options").at("largest_angle_threshold"), 125);
  EXPECT_EQ(r.at("return_code"), "MAX_ITERATION_NUMBER_REACHED");
  // Five iterations of the main phase, then at most five of each largest-angle phase.
  ASSERT_EQ(j.at("per_iteration").size(), r.at("iterations").get<std::size_t>());
  std::size_t per_phase[4] = {0, 0, 0, 0};
  for(const nlohmann::json& s : j.at("per_iteration")) ++per_phase[s.at("phase").get<std::size_t>()];
  EXPECT_EQ(per_phase[0], 5u);
  EXPECT_LE(per_phase[1], 5u);
  EXPECT_LE(per_phase[2], 5u);
  EXPECT_LE(per_phase[3], 5u);
  std::size_t moved = 0;
  for(const nlohmann::json& s : j.at("per_iteration"))
  {
    for(const char* key : {"moved", "refused", "refused_because", "topology", "insertion", "seconds"})
      EXPECT_TRUE(s.contains(key)) << key;
    moved = std::max<std::size_t>(moved, s.at("moved"));
  }
  EXPECT_GT(moved, 0u);
  for(const char* key : {"flips_2_3", "flips_3_2", "edge_removals", "multi_face_removals", "boundary_flips"})
    EXPECT_TRUE(r.at("topology").contains(key)) << key;
  for(const char* key : {"spade_splits", "wedge_splits", "cap_splits", "sliver_splits", "undone", "vertices_added"})
    EXPECT_TRUE(r.at("insertion").contains(key)) << key;
  for(const char* side : {"before", "after"})
  {
    const nlohmann::json& qr = j.at(side);
    for(const char* key : {"interior", "touching_boundary", "all_vertices_on_boundary"})
      EXPECT_TRUE(qr.at("bad_tets").contains(key)) << key;
    EXPECT_EQ(qr.at("volume_per_subdomain").size(), 2u);
  }
  EXPECT_GT(j.at("after").at("min_dihedral_deg").get<double>(), j.at("before").at("min_dihedral_deg").get<double>());
  EXPECT_LT(std::abs(j.at("max_relative_subdomain_volume_change").get<double>()), 1e-10);
  // Where the time went: every phase counted once, none more than the whole.
  double phases = 0;
  for(const char* key : {"conversion", "setup", "sweeps", "flips", "max_min", "insertion", "reread"})
  {
    const double t = r.at("phase_seconds").at(key);
    EXPECT_GE(t, 0.0) << key;
    phases += t;
  }
  const nlohmann::json& process = j.at("process_seconds");
  EXPECT_LE(phases, process.at("smoothing").get<double>());
  EXPECT_GT(process.at("read").get<double>(), 0.0);
  EXPECT_GT(process.at("quality_before_and_after").get<double>(), 0.0);
  EXPECT_GE(process.at("boundary_distance").get<double>(), 0.0);
}

// Meshes that are not what they seem say so: the run prints how many vertices it
// fixed on a crack and how many triangles it kept as embedded surfaces, the report
// gives the same counts, and a mesh with neither prints neither line.
TEST(Cli, CracksAndEmbeddedSurfacesAreCountedInTheSummary)
{
  const int n = 3;
  auto k_of = [](int v) { return v / ((n + 1) * (n + 1)); };
  auto j_of = [](int v) { return v / (n + 1) % (n + 1); };
  // Embedded: every face on the grid plane k = 2 between two cells of label 1.
  BODT::Tet_mesh embedded = test_mesh();
  std::map<std::array<int, 3>, std::vector<int>> faces;   // sorted face -> labels of its cells
  for(std::size_t t = 0; t < embedded.tets.size(); ++t)
    for(int i = 0; i < 4; ++i)
    {
      std::array<int, 3> f;
      for(int a = 0, b = 0; a < 4; ++a)
        if(a != i) f[b++] = embedded.tets[t][a];
      std::sort(f.begin(), f.end());
      faces[f].push_back(embedded.tet_labels[t]);
    }
  for(const auto& [f, labels] : faces)
    if(k_of(f[0]) == 2 && k_of(f[1]) == 2 && k_of(f[2]) == 2 && labels == std::vector<int>{1, 1})
    {
      embedded.triangles.push_back(f);
      embedded.triangle_labels.push_back(7);
    }
  ASSERT_GT(embedded.triangles.size(), 4u);
  // Crack: the vertices of plane k = 2 with j < 2 doubled, the cells above using the copies.
  BODT::Tet_mesh crack = test_mesh();
  std::map<int, int> twin;
  for(int v = 0; v < static_cast<int>(crack.points.size()); ++v)
    if(k_of(v) == 2 && j_of(v) < 2)
    {
      twin[v] = static_cast<int>(crack.points.size());
      crack.points.push_back(crack.points[v]);
      crack.vertex_refs.push_back(0);
    }
  for(auto& t : crack.tets)
    if(std::all_of(t.begin(), t.end(), [&](int v) { return k_of(v) >= 2; }))
      for(int& v : t)
        if(twin.count(v)) v = twin[v];

  const fs::path dir = tmp_dir();
  struct Case
  {
    const char* name;
    const BODT::Tet_mesh& mesh;
    std::size_t on_cracks_at_least, embedded;
  };
  const BODT::Tet_mesh plain = test_mesh();
  for(const Case& c : {Case{"plain", plain, 0, 0}, Case{"embedded", embedded, 0, embedded.triangles.size()},
                       Case{"crack", crack, 2 * twin.size(), 0}})
  {
    SCOPED_TRACE(c.name);
    const fs::path in = dir / (std::string(c.name) + ".mesh");
    BODT::IO::write_medit(in.string(), c.mesh);
    std::string out;
    ASSERT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out.mesh") + " --iterations 3 --report " +
                           q(dir / "r.json"),
                       out, dir),
              0)
        << out;
    const nlohmann::json r = nlohmann::json::parse(read_text(dir / "r.json")).at("result");
    const std::size_t on_cracks = r.at("vertices").at("on_cracks"), kept = r.at("embedded_triangles");
    EXPECT_GE(on_cracks, c.on_cracks_at_least);
    EXPECT_EQ(on_cracks > 0, c.on_cracks_at_least > 0);
    EXPECT_EQ(kept, c.embedded);
    const std::string crack_line = std::to_string(on_cracks) + " vertices fixed on cracks";
    const std::string embedded_line = std::to_string(kept) + " triangles inside subdomains kept as embedded surfaces";
    EXPECT_EQ(out.find(crack_line) != std::string::npos, on_cracks > 0) << out;
    EXPECT_EQ(out.find(embedded_line) != std::string::npos, kept > 0) << out;
    EXPECT_EQ(out.find("on cracks") != std::string::npos, on_cracks > 0) << out;
    EXPECT_EQ(out.find("embedded surfaces") != std::string::npos, kept > 0) << out;
  }
}

TEST(Cli, ZeroIterationsRunsUntilConvergence)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir);
  std::string out;
  ASSERT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out.mesh") + " --iterations 0 --report " +
                         q(dir / "r.json") + " --quiet",
                     out, dir),
            0)
      << out;
  const nlohmann::json r = nlohmann::json::parse(read_text(dir / "r.json")).at("result");
  EXPECT_LE(r.at("iterations").get<int>(), 1000);
  if(r.at("iterations") < 1000)
  {
    EXPECT_TRUE(r.at("return_code") == "CONVERGENCE_REACHED" || r.at("return_code") == "CANT_IMPROVE_ANYMORE")
        << r.at("return_code");
  }
}

TEST(Cli, FormatOptionChoosesTheWriter)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir);
  std::string out;
  ASSERT_EQ(run_bodt("convert " + q(in) + " " + q(dir / "out.msh") + " --format msh22", out, dir), 0) << out;
  EXPECT_EQ(read_text(dir / "out.msh").rfind("$MeshFormat\n2.2", 0), 0u);
  ASSERT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "plain") + " --format vtu --quiet", out, dir), 0) << out;
  EXPECT_NE(read_text(dir / "plain").find("<VTKFile"), std::string::npos);
  EXPECT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out.mesh") + " --method flips --no-flips", out, dir), 2);
}

// `quality` writes nothing, so it does not say that skipped sections will not be written back.
// The output file is the same, byte for byte, on any number of threads.
TEST(Cli, ThreadsDoNotChangeTheOutputBytes)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir);
  std::string out, reference;
  for(const char* threads : {"1", "2", "4"})
  {
    const fs::path result = dir / (std::string("out") + threads + ".mesh");
    ASSERT_EQ(run_bodt("smooth " + q(in) + " -o " + q(result) + " --quiet --threads " + threads, out, dir), 0) << out;
    std::ifstream file(result, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if(reference.empty())
      reference = bytes;
    else
      EXPECT_TRUE(bytes == reference) << threads << " threads";
  }
  std::ifstream original(in, std::ios::binary);
  EXPECT_NE(std::string((std::istreambuf_iterator<char>(original)), std::istreambuf_iterator<char>()), reference);
  EXPECT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "x.mesh") + " --threads -1", out, dir), 2);
}

TEST(Cli, QualityDoesNotTalkAboutWritingBack)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir);
  std::string text = read_text(in);
  const std::size_t end = text.rfind("End");
  ASSERT_NE(end, std::string::npos);
  text.insert(end, "Normals\n1\n0 0 1\n");
  std::ofstream(dir / "normals.mesh") << text;
  std::string out;
  ASSERT_EQ(run_bodt("quality " + q(dir / "normals.mesh"), out, dir), 0) << out;
  EXPECT_NE(out.find("Normals"), std::string::npos) << out;
  EXPECT_EQ(out.find("written back"), std::string::npos) << out;
  ASSERT_EQ(run_bodt("quality --json " + q(in), out, dir), 0) << out;
  EXPECT_EQ(nlohmann::json::parse(out).at("num_tets"), 162);
}

// `bodt compare` on the user's own file runs bodt-compare on that file only, and
// its text does not describe the benchmark.
TEST(Cli, CompareOnOwnFileHasNoBenchmarkWording)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir);
  std::string out;
  ASSERT_EQ(run_bodt("compare --quiet " + q(in), out, dir), 0) << out;
  EXPECT_NE(out.find("your meshes"), std::string::npos) << out;
  EXPECT_NE(out.find("| in |"), std::string::npos) << out;
  for(const char* benchmark : {"benchmark", "results.sh", "40,000", "generated", "paper's figures"})
    EXPECT_EQ(out.find(benchmark), std::string::npos) << benchmark << " in\n" << out;
}

// A --stellar path that is not there is refused before any work.
TEST(Cli, CompareRefusesAMissingStellar)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir);
  std::string out;
  EXPECT_NE(run_bodt("compare --quiet --stellar " + q(dir / "no_stellar") + " " + q(in), out, dir), 0) << out;
  EXPECT_NE(out.find("--stellar"), std::string::npos) << out;
  EXPECT_NE(out.find("no_stellar"), std::string::npos) << out;
}

namespace {

std::string progress_text(bool quiet, std::size_t iterations, double time_limit, double seconds_per_sweep,
                          std::size_t sweeps)
{
  std::FILE* f = std::tmpfile();
  BODT::Smoothing_options o;
  o.max_iteration_number = iterations;
  o.time_limit = time_limit;
  bodt_cli::Progress progress(quiet, o, f);
  for(std::size_t i = 1; i <= sweeps; ++i)
  {
    BODT::Iteration_stats s;
    s.iteration = i;
    s.seconds = seconds_per_sweep * static_cast<double>(i);
    progress.after_iteration(s);
  }
  progress.finish();
  std::rewind(f);
  std::string text;
  for(int c; (c = std::fgetc(f)) != EOF;) text += static_cast<char>(c);
  std::fclose(f);
  EXPECT_EQ(progress.iterations().size(), sweeps);
  return text;
}

} // namespace

TEST(Progress, ShowsTotalAndTimeLeftOnlyOnLongRuns)
{
  // 1.5 s a sweep: after sweep 3 of at most 80 (20 in each of the four phases),
  // 77 sweeps or 115.5 s are left at most.
  const std::string text = progress_text(false, 20, 0, 1.5, 3);
  EXPECT_NE(text.find("sweep 3 of at most 80"), std::string::npos) << text;
  EXPECT_NE(text.find("about 116 s left"), std::string::npos) << text;
  // The first sweep ended before 1 s had passed: no line for it.
  EXPECT_EQ(progress_text(false, 20, 0, 0.4, 2), "");
  EXPECT_EQ(progress_text(true, 20, 0, 1.5, 3), "");
  // A time limit bounds the estimate; 0 iterations show the cap.
  EXPECT_NE(progress_text(false, 20, 6.2, 1.5, 3).find("about 2 s left"), std::string::npos);
  EXPECT_NE(progress_text(false, 0, 0, 1.5, 1).find("until convergence, at most 4000"), std::string::npos);
}

// Issue 30: two grids that share only an edge, or only a vertex, cannot form a
// triangulation; the refusal named no file ("error: : the boundary ...").
TEST(Cli, RefusalsOfTheConversionNameTheFile)
{
  const fs::path dir = tmp_dir();
  for(const auto& [shift, words] : {std::make_pair(std::array<int, 3>{2, 2, 0}, "the boundary is not manifold at edge"),
                                    std::make_pair(std::array<int, 3>{2, 2, 2}, "the mesh is not manifold at vertex")})
  {
    const fs::path in = dir / "two_grids.mesh";
    BODT::IO::write_medit(in.string(), touching_grids(2, shift));
    std::string out;
    EXPECT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out.mesh"), out, dir), 1) << out;
    EXPECT_NE(out.find("bodt smooth: error: " + in.string() + ": " + words), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(dir / "out.mesh"));
  }
}

namespace {

// Runs the tool; `out` gets its standard output alone, `err` its standard error.
int run_bodt_apart(const std::string& args, std::string& out, std::string& err, const fs::path& dir)
{
  const fs::path o = dir / "stdout.txt", e = dir / "stderr.txt";
  const int status = std::system((std::string(BODT_BINARY) + " " + args + " > " + q(o) + " 2> " + q(e)).c_str());
  out = read_text(o);
  err = read_text(e);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

} // namespace

// --json prints on standard output the report --report writes, as one line, and
// nothing else; the messages stay on standard error.
TEST(Cli, JsonPrintsTheReportOnStandardOutput)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir);
  std::string out, err;
  ASSERT_EQ(run_bodt_apart("smooth " + q(in) + " -o " + q(dir / "out.mesh") + " --iterations 3 --json --report " +
                               q(dir / "r.json"),
                           out, err, dir),
            0)
      << out << err;
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.find('\n'), out.size() - 1) << "one line";
  const nlohmann::json printed = nlohmann::json::parse(out);
  EXPECT_EQ(printed, nlohmann::json::parse(read_text(dir / "r.json")));
  EXPECT_EQ(printed.at("options").at("max_iteration_number"), 3);
  EXPECT_NE(err.find("interior"), std::string::npos) << "the classification goes to stderr: " << err;
  EXPECT_EQ(err.find("min dihedral"), std::string::npos) << "no table with --json: " << err;
  // Without --report too; and --quiet silences stderr, not the JSON asked for.
  ASSERT_EQ(run_bodt_apart("smooth " + q(in) + " -o " + q(dir / "out2.mesh") + " --json --quiet", out, err, dir), 0);
  EXPECT_EQ(err, "");
  EXPECT_EQ(nlohmann::json::parse(out).at("output"), (dir / "out2.mesh").string());
  // A failed run prints no JSON.
  ASSERT_EQ(run_bodt_apart("smooth " + q(dir / "missing.mesh") + " -o " + q(dir / "out3.mesh") + " --json", out, err,
                           dir),
            1);
  EXPECT_EQ(out, "");
}

namespace {

// The boundary star of the origin: two flat half-planes meeting along the x axis,
// their normals turning by `turn` degrees (classification/classification.cpp's folded star).
BODT::internal::Vertex_star<BODT::Tet_mesh::Kernel> folded_star(double turn)
{
  BODT::internal::Vertex_star<BODT::Tet_mesh::Kernel> star;
  star.x0 = Point(0, 0, 0);
  const double f = turn * CGAL_PI / 180;
  std::vector<Point> ring;
  for(int i = 0; i <= 3; ++i) ring.emplace_back(std::cos(CGAL_PI * i / 3), std::sin(CGAL_PI * i / 3), 0);
  for(int i = 1; i < 5; ++i)
  {
    const double a = CGAL_PI + CGAL_PI * i / 5;
    ring.emplace_back(std::cos(a), std::sin(a) * std::cos(f), std::sin(a) * std::sin(f));
  }
  for(std::size_t i = 0; i < ring.size(); ++i) star.boundary.push_back({ring[i], ring[(i + 1) % ring.size()]});
  return star;
}

// The apex of a symmetric three-sided corner whose normals are `apart` degrees
// apart: normals n_k at angle b from the z axis, 120 degrees apart around it, with
// cos(apart) = 1 - 3/2 sin^2 b; side k lies between the edges it shares with its
// neighbours, which run down from the apex.
BODT::internal::Vertex_star<BODT::Tet_mesh::Kernel> corner_star(double apart)
{
  using Vector = BODT::Tet_mesh::Kernel::Vector_3;
  const double b = std::asin(std::sqrt((1 - std::cos(apart * CGAL_PI / 180)) / 1.5));
  std::vector<Vector> n;
  for(int k = 0; k < 3; ++k)
  {
    const double t = 2 * CGAL_PI * k / 3;
    n.emplace_back(std::sin(b) * std::cos(t), std::sin(b) * std::sin(t), std::cos(b));
  }
  BODT::internal::Vertex_star<BODT::Tet_mesh::Kernel> star;
  star.x0 = Point(0, 0, 0);
  auto edge = [&](int i, int j) {   // the downward direction shared by sides i and j
    Vector e = CGAL::cross_product(n[i], n[j]);
    return e.z() < 0 ? e : -e;
  };
  for(int k = 0; k < 3; ++k)
  {
    const Point a = CGAL::ORIGIN + edge(k, (k + 2) % 3), c = CGAL::ORIGIN + edge(k, (k + 1) % 3);
    // Ordered so that (a - x0) x (c - x0) points along the side's outward normal.
    if(CGAL::cross_product(a - CGAL::ORIGIN, c - CGAL::ORIGIN) * n[k] > 0)
      star.boundary.push_back({a, c});
    else
      star.boundary.push_back({c, a});
  }
  return star;
}

} // namespace

// The angles map to the ratios tensor voting compares: an edge whose sides turn by
// a bit more than --feature-angle is a feature, by a bit less it is not; the same
// for corners and --corner-angle. And the defaults are the library's ratios.
TEST(FeatureAngles, MapToTheRatiosTensorVotingUses)
{
  for(double angle : {10.0, 25.0, 40.0, 60.0, 85.0})
  {
    BODT::Tensor_voting_options o;
    o.edge_ratio = bodt_cli::edge_ratio_of_angle(angle);
    o.corner_ratio = 1;
    EXPECT_EQ(BODT::internal::tensor_vote(folded_star(angle * 1.001), o).kind, BODT::internal::Voted_kind::feature) << angle;
    EXPECT_EQ(BODT::internal::tensor_vote(folded_star(angle * 0.999), o).kind, BODT::internal::Voted_kind::surface) << angle;
    // Votes have no sign: a blade turning by 180 - angle looks the same.
    EXPECT_EQ(BODT::internal::tensor_vote(folded_star(180 - angle * 1.001), o).kind, BODT::internal::Voted_kind::feature) << angle;
    EXPECT_NEAR(bodt_cli::angle_of_edge_ratio(o.edge_ratio), angle, 1e-9);

    BODT::Tensor_voting_options c;
    c.corner_ratio = bodt_cli::corner_ratio_of_angle(angle);
    EXPECT_EQ(BODT::internal::tensor_vote(corner_star(angle * 1.001), c).kind, BODT::internal::Voted_kind::corner) << angle;
    EXPECT_NE(BODT::internal::tensor_vote(corner_star(angle * 0.999), c).kind, BODT::internal::Voted_kind::corner) << angle;
    EXPECT_NEAR(bodt_cli::angle_of_corner_ratio(c.corner_ratio), angle, 1e-9);
  }
  EXPECT_NEAR(bodt_cli::corner_ratio_of_angle(90), 1.0, 1e-15) << "a cube corner";
  EXPECT_NEAR(bodt_cli::edge_ratio_of_angle(90), 1.0, 1e-15);
  const BODT::Tensor_voting_options defaults;
  EXPECT_NEAR(bodt_cli::angle_of_edge_ratio(defaults.edge_ratio), 25.21, 0.005);
  EXPECT_NEAR(bodt_cli::angle_of_corner_ratio(defaults.corner_ratio), 30.27, 0.005);
}

namespace {

// The box [0, 4]^3 with a roof: the top rises to a ridge along y at x = 2 whose two
// sides turn by 30 degrees. No feature information: tensor voting classifies.
BODT::Tet_mesh roofed_box()
{
  const int n = 4;
  BODT::Tet_mesh m = cube_grid(n, [](int, int, int) { return 1; });
  const double slope = std::tan(15 * CGAL_PI / 180);
  for(Point& p : m.points)
    p = Point(p.x(), p.y(), p.z() * (1 + slope * (2 - std::abs(p.x() - 2)) / n));
  return m;
}

nlohmann::json vertices_with(const fs::path& dir, const fs::path& in, const std::string& options)
{
  std::string out;
  EXPECT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out.mesh") + " --iterations 1 --quiet --report " +
                         q(dir / "r.json") + " " + options,
                     out, dir),
            0)
      << options << "\n" << out;
  return nlohmann::json::parse(read_text(dir / "r.json"));
}

} // namespace

// On the roofed box the three inner vertices of the ridge (sides turning by 30
// degrees) are feature vertices below a feature angle of 30 and surface vertices
// above; its two ends (a 150-degree wall between two roof sides) are corners below
// a corner angle of 35.7 and feature vertices above. No option: the library's ratios.
TEST(FeatureAngles, OptionsChangeTheClassification)
{
  const fs::path dir = tmp_dir();
  const fs::path in = dir / "roof.mesh";
  BODT::IO::write_medit(in.string(), roofed_box());
  auto count = [](const nlohmann::json& r, const char* kind) {
    return r.at("result").at("vertices").at(kind).get<int>();
  };
  const nlohmann::json plain = vertices_with(dir, in, "");
  EXPECT_TRUE(plain.at("result").at("vertices").at("tensor_voting").get<bool>());
  EXPECT_EQ(plain.at("options").at("tensor_voting").at("edge_ratio"), BODT::Tensor_voting_options().edge_ratio);
  EXPECT_EQ(plain.at("options").at("tensor_voting").at("corner_ratio"), BODT::Tensor_voting_options().corner_ratio);

  const nlohmann::json sharp = vertices_with(dir, in, "--feature-angle 25");
  const nlohmann::json blunt = vertices_with(dir, in, "--feature-angle 35");
  EXPECT_NEAR(sharp.at("options").at("tensor_voting").at("edge_ratio").get<double>(),
              std::pow(std::tan(12.5 * CGAL_PI / 180), 2), 1e-15);
  EXPECT_NEAR(sharp.at("options").at("tensor_voting").at("feature_angle_deg").get<double>(), 25, 1e-12);
  EXPECT_EQ(count(sharp, "feature") - count(blunt, "feature"), 3);
  EXPECT_EQ(count(blunt, "surface") - count(sharp, "surface"), 3);
  EXPECT_EQ(count(sharp, "fixed"), count(blunt, "fixed"));
  EXPECT_EQ(count(plain, "feature"), count(sharp, "feature")) << "the default 25.21 degrees finds the ridge";

  const nlohmann::json cornered = vertices_with(dir, in, "--corner-angle 30");
  const nlohmann::json open = vertices_with(dir, in, "--corner-angle 40");
  EXPECT_EQ(count(cornered, "fixed") - count(open, "fixed"), 2);
  EXPECT_EQ(count(open, "feature") - count(cornered, "feature"), 2);
  EXPECT_NEAR(open.at("options").at("tensor_voting").at("corner_ratio").get<double>(),
              bodt_cli::corner_ratio_of_angle(40), 1e-15);
}

// Bad angles and planes are refused before any work with exit status 2 and a
// message naming the option; options that cannot act are said to be unused.
TEST(FeatureAngles, BadValuesAreRefusedAndUnusedOnesReported)
{
  const fs::path dir = tmp_dir();
  const fs::path in = write_test_mesh(dir);
  struct Case
  {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      {"--feature-angle 0", "--feature-angle"},
      {"--feature-angle 90.5", "--feature-angle"},
      {"--feature-angle sharp", "--feature-angle"},
      {"--corner-angle -10", "--corner-angle"},
      {"--feature-angle 30 --no-features", "--no-features"},
      {"--cut z=1", "--html"},
      {"--html " + q(dir / "p.html") + " --cut 1,2", "not a plane"},
      {"--html " + q(dir / "p.html") + " --cut 0,0,0,0,0,0", "must not be zero"},
      {"--html " + q(dir / "p.html") + " --cut z=100", "misses the mesh"},
  };
  // What an earlier run of this test wrote.
  fs::remove(dir / "out.mesh");
  fs::remove(dir / "p.html");
  for(const Case& c : cases)
  {
    std::string out;
    EXPECT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out.mesh") + " " + c.args, out, dir), 2) << c.args;
    EXPECT_NE(out.find(c.message), std::string::npos) << c.args << "\n" << out;
    EXPECT_FALSE(fs::exists(dir / "out.mesh")) << c.args;
    EXPECT_FALSE(fs::exists(dir / "p.html")) << c.args;
  }
  // Boundary vertices that do not move are not classified: the angle is said to be unused.
  std::string out;
  ASSERT_EQ(run_bodt("smooth " + q(in) + " -o " + q(dir / "out.mesh") + " --method odt --feature-angle 40", out, dir), 0);
  EXPECT_NE(out.find("--feature-angle and --corner-angle were not used: boundary vertices do not move with --method odt"),
            std::string::npos)
      << out;
  // A mesh with feature edges of its own still votes inside its patches (issue 30): the angle is used.
  BODT::Tet_mesh edged = test_mesh();
  edged.edges.push_back({0, 1});
  edged.edge_labels.push_back(1);
  const fs::path with_edges = dir / "edges.mesh";
  BODT::IO::write_medit(with_edges.string(), edged);
  ASSERT_EQ(run_bodt("smooth " + q(with_edges) + " -o " + q(dir / "out.mesh") + " --feature-angle 40", out, dir), 0);
  EXPECT_EQ(out.find("not used"), std::string::npos) << out;
}
