// LUT files through OpenColorIO: a .cube the test writes (a known function on a 17^3 lattice) is
// applied as the tetrahedral interpolation of its lattice (OpenColorIO's tools' INTERP_BEST), a CLF file asking for tetrahedral
// interpolation gets it, DOMAIN_MIN/MAX and 1D LUTs do what the format says, every file kept in
// tests/data/luts loads, an exported .cube reads back to the same LUT, and every kind of bad file
// gives one line naming it.

#include "test_paths.hpp"
#include "lut_support.hpp"
#include "scenes/temp_dir.hpp"

#include "luxel/postfx/grade.hpp"
#include "luxel/postfx/lut_file.hpp"
#include "luxel/postfx/lut_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

namespace luxel::postfx {
namespace {

using scenes::test::TempDir;

/// Colors that exercise every cell: random, plus the corners and lattice-aligned values.
std::vector<glm::vec3> probe_colors(int count) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> d(0.0f, 1.0f);
  std::vector<glm::vec3> colors = {glm::vec3(0.0f), glm::vec3(1.0f), glm::vec3(1.0f, 0.0f, 0.5f), glm::vec3(0.5f)};
  for (int i = 0; i < count; ++i) colors.push_back(glm::vec3(d(rng), d(rng), d(rng)));
  return colors;
}

/// The largest difference between the file's transform and `reference` over the probe colors.
template <class Reference>
double max_error(const ColorTransform& t, Reference&& reference) {
  const std::vector<glm::vec3> in = probe_colors(4000);
  std::vector<glm::vec3> out = in;
  t.apply(out);
  double worst = 0.0;
  for (size_t i = 0; i < in.size(); ++i) {
    const glm::dvec3 want = reference(glm::dvec3(in[i]));
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(out[i][c]) - want[c]));
  }
  return worst;
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(LutFile, CubeIsAppliedAsTheTetrahedralInterpolationOfItsLattice) {
  const TempDir dir;
  const test::Lattice lattice = test::analytic_lattice(17);
  test::write_cube_file(lattice, dir.file("analytic.cube"));
  const ColorTransform t = read_lut_file(dir.file("analytic.cube"));
  EXPECT_EQ(t.description, "3D LUT 17^3, tetrahedral");
  const double err = max_error(t, [&](glm::dvec3 c) { return test::tetrahedral(lattice, c); });
  EXPECT_LE(err, 1e-5);
  // The lattice is coarse enough that interpolating it is not the function itself, and not
  // trilinear either: the comparison above decides between them.
  EXPECT_GT(max_error(t, [](glm::dvec3 c) { return test::analytic_grade(c); }), 1e-3);
  EXPECT_GT(max_error(t, [&](glm::dvec3 c) { return test::trilinear(lattice, c); }), 1e-4);
  std::printf("17^3 .cube: OpenColorIO vs tetrahedral in double: max %.3g\n", err);
}

TEST(LutFile, ClfFileGetsTheInterpolationItAsksFor) {
  const TempDir dir;
  const test::Lattice lattice = test::analytic_lattice(9);
  test::write_clf_file(lattice, dir.file("tetrahedral.clf"), "tetrahedral");
  test::write_clf_file(lattice, dir.file("trilinear.clf"), "trilinear");
  const ColorTransform tet = read_lut_file(dir.file("tetrahedral.clf"));
  const ColorTransform tri = read_lut_file(dir.file("trilinear.clf"));
  EXPECT_EQ(tet.description, "3D LUT 9^3, tetrahedral");
  EXPECT_EQ(tri.description, "3D LUT 9^3, trilinear");
  EXPECT_LE(max_error(tet, [&](glm::dvec3 c) { return test::tetrahedral(lattice, c); }), 1e-5);
  EXPECT_LE(max_error(tri, [&](glm::dvec3 c) { return test::trilinear(lattice, c); }), 1e-5);
  EXPECT_GT(max_error(tet, [&](glm::dvec3 c) { return test::trilinear(lattice, c); }), 1e-4);
}

TEST(LutFile, DomainMinMaxMapsTheInputOntoTheLattice) {
  const TempDir dir;
  const test::Lattice lattice = test::analytic_lattice(5);
  test::write_cube_file(lattice, dir.file("plain.cube"));
  std::ifstream plain(dir.file("plain.cube"));
  std::string text((std::istreambuf_iterator<char>(plain)), std::istreambuf_iterator<char>());
  text.insert(text.find("LUT_3D_SIZE"), "DOMAIN_MIN 0.1 0.2 0\nDOMAIN_MAX 0.9 1 0.5\n");
  write(dir.file("domain.cube"), text);
  const glm::dvec3 lo(0.1, 0.2, 0.0), hi(0.9, 1.0, 0.5);
  const double err = max_error(read_lut_file(dir.file("domain.cube")), [&](glm::dvec3 c) {
    return test::tetrahedral(lattice, glm::clamp((c - lo) / (hi - lo), 0.0, 1.0));
  });
  EXPECT_LE(err, 1e-5);
}

TEST(LutFile, OneDimensionalCubeInterpolatesEachChannel) {
  const TempDir dir;
  // Per channel: r squared-ish, g inverted, b a step up then flat.
  const double table[4][3] = {{0.0, 1.0, 0.1}, {0.2, 0.6, 0.8}, {0.5, 0.3, 0.9}, {1.0, 0.0, 0.9}};
  std::string text = "LUT_1D_SIZE 4\n";
  for (const auto& row : table) text += std::to_string(row[0]) + " " + std::to_string(row[1]) + " " + std::to_string(row[2]) + "\n";
  write(dir.file("curve.cube"), text);
  const ColorTransform t = read_lut_file(dir.file("curve.cube"));
  EXPECT_EQ(t.description, "1D LUT 4");
  const double err = max_error(t, [&](glm::dvec3 c) {
    glm::dvec3 out;
    for (int ch = 0; ch < 3; ++ch) {
      int i0;
      double f;
      test::locate(c[ch], 4, i0, f);
      out[ch] = table[i0][ch] + f * (table[i0 + 1][ch] - table[i0][ch]);
    }
    return out;
  });
  EXPECT_LE(err, 1e-5);
}

TEST(LutFile, EveryFileOfTheTestDataLoads) {
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(luxel::test::data_dir() + "/luts")) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".cube" && ext != ".3dl") continue;
    const ColorTransform t = read_lut_file(entry.path().string());
    const Lut lut = sample_lut(t);
    EXPECT_NE(lut, Lut::identity()) << entry.path() << " changes colors";
    std::printf("%s: %s\n", entry.path().filename().c_str(), t.description.c_str());
    ++files;
  }
  EXPECT_EQ(files, 6);
}

TEST(LutFile, OpenColorIOTestFilesMeanWhatTheirFormatsSay) {
  // iridas_3d.cube: a 2^3 LUT doubling each channel over DOMAIN_MIN (0, 1, 0) .. DOMAIN_MAX (2, 2, 1).
  const ColorTransform t = read_lut_file(luxel::test::data_dir() + "/luts/opencolorio/iridas_3d.cube");
  std::vector<glm::vec3> c = {glm::vec3(0.5f, 0.25f, 0.75f), glm::vec3(1.0f, 1.0f, 0.2f)};
  t.apply(c);
  // r: 2 (r - 0) / 2; g below its domain clamps to 0; b: 2 (b - 0) / 1.
  EXPECT_NEAR(c[0].x, 0.5f, 1e-6f);
  EXPECT_NEAR(c[0].y, 0.0f, 1e-6f);
  EXPECT_NEAR(c[0].z, 1.5f, 1e-6f);
  EXPECT_NEAR(c[1].x, 1.0f, 1e-6f);
  EXPECT_NEAR(c[1].z, 0.4f, 1e-6f);
}

TEST(LutFile, ExportedCubeReadsBackAsTheSameLut) {
  const TempDir dir;
  const Lut warm = resolve_lut("builtin:warm");
  write_cube(warm, dir.file("warm.cube"), "builtin:warm \"quoted\"");
  const ColorTransform back = read_lut_file(dir.file("warm.cube"));
  EXPECT_EQ(back.description, "3D LUT 32^3, tetrahedral");
  EXPECT_EQ(sample_lut(back), warm) << "the lattice points coincide: every entry reads back as written";
  EXPECT_NE(warm, Lut::identity());
  EXPECT_THROW(write_cube(warm, dir.file("no/such/folder/x.cube"), "x"), std::runtime_error);
}

TEST(LutFile, ReadingAgainAfterTheFileChangedReadsTheNewFile) {
  const TempDir dir;
  write_cube(Lut::identity(), dir.file("changing.cube"), "identity");
  EXPECT_EQ(sample_lut(read_lut_file(dir.file("changing.cube"))), Lut::identity());
  const Lut cool = resolve_lut("builtin:cool");
  write_cube(cool, dir.file("changing.cube"), "cool");
  EXPECT_EQ(sample_lut(read_lut_file(dir.file("changing.cube"))), cool) << "not OpenColorIO's cached copy";
}

/// Reading `path` throws a runtime_error of one line that starts with the path and holds `problem`.
void expect_one_line(const std::string& path, const std::string& problem) {
  try {
    read_lut_file(path);
    ADD_FAILURE() << path << " was read";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_TRUE(std::all_of(what.begin(), what.end(), [](char c) { return c >= 0x20 && c < 0x7f; })) << what;
    EXPECT_NE(what.find(problem), std::string::npos) << "'" << problem << "' not in: " << what;
    std::printf("%s\n", what.c_str());
  }
}

TEST(LutFile, BadFilesGiveOneLineNamingTheFile) {
  const TempDir dir;
  const std::string corners = "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n";
  write(dir.file("garbage.cube"), "garbage \x01\x02 not a lut\n");
  write(dir.file("empty.cube"), "");
  write(dir.file("truncated.cube"), "LUT_3D_SIZE 3\n" + corners);
  write(dir.file("size0.cube"), "LUT_3D_SIZE 0\n");
  write(dir.file("size1.cube"), "LUT_3D_SIZE 1\n0 0 0\n");
  write(dir.file("size300.cube"), "LUT_3D_SIZE 300\n0 0 0\n");
  write(dir.file("size-lower-case.cube"), "LuT_3D_SIZE 20880/");  // found by fuzz_lut
  write(dir.file("size1d.cube"), "LUT_1D_SIZE 100000000\n0 0 0\n");
  write(dir.file("nan.cube"), "LUT_3D_SIZE 2\n" + corners + "nan 1 1\n");
  write(dir.file("inf.cube"), "LUT_3D_SIZE 2\n" + corners + "1 inf 1\n");
  write(dir.file("one.spi3d"), "SPILUT 1.0\n3 3\n1 1 1\n0 0 0 0.5 0.5 0.5\n");
  write(dir.file("big.spi3d"), "SPILUT 1.0\n3 3\n1000 1000 1000\n0 0 0 0 0 0\n");
  write(dir.file("notes.txt"), "dear diary\n");
  write(dir.file("image.cube"), "\x89PNG\r\n\x1a\n\x01\x02");
  std::filesystem::create_directory(dir.file("folder.cube"));

  expect_one_line(dir.file("missing.cube"), "cannot open it");
  expect_one_line(dir.file("folder.cube"), "cannot open it");
  expect_one_line(dir.file("garbage.cube"), "not a LUT OpenColorIO reads: ");
  expect_one_line(dir.file("empty.cube"), "not a LUT OpenColorIO reads: ");
  expect_one_line(dir.file("truncated.cube"), "Found 7, expected 27");
  expect_one_line(dir.file("size0.cube"), "LUT_3D_SIZE 0: a LUT needs at least 2 points");
  expect_one_line(dir.file("size1.cube"), "LUT_3D_SIZE 1: a LUT needs at least 2 points");
  expect_one_line(dir.file("size300.cube"), "LUT_3D_SIZE 300 is above 129");
  expect_one_line(dir.file("size-lower-case.cube"), "LuT_3D_SIZE 20880 is above 129");
  expect_one_line(dir.file("size1d.cube"), "LUT_1D_SIZE 100000000 is above 1048576");
  expect_one_line(dir.file("nan.cube"), "a NaN or infinite value in its 3D LUT");
  expect_one_line(dir.file("inf.cube"), "a NaN or infinite value in its 3D LUT");
  expect_one_line(dir.file("one.spi3d"), "a 3D LUT of 1 point per axis cannot interpolate");
  expect_one_line(dir.file("big.spi3d"), "Grid size '1000' must not be greater than '129'");
  expect_one_line(dir.file("notes.txt"), "not a LUT OpenColorIO reads: ");  // every reader tried
  expect_one_line(dir.file("image.cube"), "At line (1): '?PNG'. Malformed");
}

// NaN and infinity in each format's numbers: every one is refused in one line naming the file.
// Text formats spell them "nan" and "inf"; a value beyond float (1e999, 1e300) is infinity once
// read, or refused by the format's reader as malformed. (.raw holds bytes: no NaN can be written.)
TEST(LutFile, NanAndInfinityInEveryFormat) {
  const TempDir dir;
  const std::string corners = "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n";
  const std::string spi3d = "SPILUT 1.0\n3 3\n2 2 2\n0 0 0 0 0 0\n0 0 1 0 0 1\n0 1 0 0 1 0\n0 1 1 0 1 1\n"
                            "1 0 0 1 0 0\n1 0 1 1 0 1\n1 1 0 1 1 0\n1 1 1 ";
  const std::string csp = "CSPLUTV100\n3D\n\n2\n0.0 1.0\n0.0 1.0\n2\n0.0 1.0\n0.0 1.0\n2\n0.0 1.0\n0.0 1.0\n\n2 2 2\n" + corners;
  auto clf = [](const std::string& body) {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<ProcessList id=\"t\" compCLFversion=\"3\">\n" + body + "</ProcessList>\n";
  };
  auto matrix = [&](const std::string& v) {
    return clf("<Matrix inBitDepth=\"32f\" outBitDepth=\"32f\"><Array dim=\"3 3\">" + v + " 0 0 0 1 0 0 0 1</Array></Matrix>\n");
  };
  auto cdl = [](const std::string& slope) {
    return "<ColorCorrection id=\"c\"><SOPNode><Slope>" + slope +
           " 1 1</Slope><Offset>0 0 0</Offset><Power>1 1 1</Power></SOPNode><SatNode><Saturation>1</Saturation></SatNode></ColorCorrection>\n";
  };
  const std::pair<std::string, std::string> files[] = {
      {"nan1d.cube", "LUT_1D_SIZE 2\n0 0 0\nnan 1 1\n"},
      {"inf1d.cube", "LUT_1D_SIZE 2\n0 0 0\n1 -inf 1\n"},
      {"huge.cube", "LUT_3D_SIZE 2\n" + corners + "1 1 1e300\n"},
      {"nan.spi1d", "Version 1\nFrom 0.0 1.0\nLength 2\nComponents 1\n{\n0.0\nnan\n}\n"},
      {"inf.spi1d", "Version 1\nFrom 0.0 1.0\nLength 2\nComponents 1\n{\n0.0\ninf\n}\n"},
      {"nan.spi3d", spi3d + "nan 1 1\n"},
      {"inf.spi3d", spi3d + "1 inf 1\n"},
      {"nan.csp", csp + "nan 1 1\n"},
      {"inf.csp", csp + "1 1 inf\n"},
      {"nan-matrix.clf", matrix("nan")},
      {"inf-matrix.clf", matrix("inf")},
      {"huge-matrix.clf", matrix("1e300")},
      {"nan-lut.clf", clf("<LUT1D inBitDepth=\"32f\" outBitDepth=\"32f\"><Array dim=\"2 3\">0 0 0 nan 1 1</Array></LUT1D>\n")},
      {"nan-range.clf", clf("<Range inBitDepth=\"32f\" outBitDepth=\"32f\"><minInValue>nan</minInValue><maxInValue>1</maxInValue>"
                            "<minOutValue>0</minOutValue><maxOutValue>1</maxOutValue></Range>\n")},
      {"nan.cc", cdl("nan")},
      {"inf.cc", cdl("inf")},
  };
  for (const auto& [name, text] : files) {
    write(dir.file(name), text);
    expect_one_line(dir.file(name), "");
  }
  // A NaN domain is read (OpenColorIO's .spi1d reader lets it through) and gives finite colors.
  write(dir.file("nan-domain.spi1d"), "Version 1\nFrom nan 1.0\nLength 2\nComponents 1\n{\n0.0\n1.0\n}\n");
  std::vector<glm::vec3> colors = {glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(1.0f), glm::vec3(2.0f)};
  read_lut_file(dir.file("nan-domain.spi1d")).apply(colors);
  for (const glm::vec3& c : colors) EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
}

TEST(LutSource, NamesPickPresetsOrFiles) {
  const ColorTransform warm = color_transform_named("builtin:warm");
  EXPECT_EQ(warm.name, "builtin:warm");
  EXPECT_EQ(warm.description, "grade: color balance");
  for (const std::string& preset : grade_preset_names()) EXPECT_NO_THROW(resolve_lut("builtin:" + preset)) << preset;
  try {
    color_transform_named("builtin:sepia");
    ADD_FAILURE() << "builtin:sepia was found";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "builtin:sepia: unknown built-in LUT 'sepia' (known: builtin:day-for-night, builtin:archival, "
                           "builtin:warm, builtin:cool)");
  }
  EXPECT_THROW(color_transform_named("no-such-file.cube"), std::runtime_error);
}

}  // namespace
}  // namespace luxel::postfx
