// The enums' name tables (enum_names.h): each table names every value once, toString and the
// parse functions read it both ways, and the helpers give the command line's choice lists and the
// messages' "a, b or c".
#include <cctype>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "shadowvol/enum_names.h"
#include "shadowvol/frame.h"
#include "shadowvol/scene.h"

namespace shadowvol {
namespace {

// Every value of `table` once and every name once; toString(value) is its name and `parse` reads
// the name back to the value; an unknown name (and an empty one, and one off by case) is refused
// without touching the output.
template <class E, std::size_t N, class Parse>
void expectRoundTrip(const EnumNames<E, N>& table, Parse parse, const char* what) {
  std::set<E> values;
  std::set<std::string> names;
  for (const EnumName<E>& e : table) {
    EXPECT_TRUE(values.insert(e.value).second) << what << ": value twice, named " << e.name;
    EXPECT_TRUE(names.insert(e.name).second) << what << ": name twice: " << e.name;
    EXPECT_STREQ(toString(e.value), e.name) << what;
    E parsed = table[(&e - table.data() + 1) % N].value;  // another value, so a no-op would show
    EXPECT_TRUE(parse(e.name, parsed)) << what << ": " << e.name;
    EXPECT_EQ(parsed, e.value) << what << ": " << e.name;
  }
  for (const std::string& bad : {std::string(), std::string("no-such-name"), std::string(table[0].name) + " "}) {
    E untouched = table[0].value;
    EXPECT_FALSE(parse(bad, untouched)) << what << ": '" << bad << "'";
    EXPECT_EQ(untouched, table[0].value) << what;
  }
  std::string upper = table[0].name;
  for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
  E untouched = table[0].value;
  EXPECT_FALSE(parse(upper, untouched)) << what << ": names are case-sensitive";
}

TEST(EnumNames, EveryTableRoundTripsThroughToStringAndParse) {
  expectRoundTrip(kCaptureModeNames, parseCaptureMode, "CaptureMode");
  expectRoundTrip(kTriangulationNames, parseTriangulation, "Triangulation");
  expectRoundTrip(kFarCapNames, parseFarCap, "FarCap");
  expectRoundTrip(kLightTypeNames, parseLightType, "LightType");
  expectRoundTrip(kLightFitNames, parseLightFit, "LightFit");
  expectRoundTrip(kShadowMethodNames, parseShadowMethod, "ShadowMethod");
  expectRoundTrip(kVolumeSourceNames, parseVolumeSource, "VolumeSource");
  expectRoundTrip(kRefineCrossingsNames, parseRefineCrossings, "RefineCrossings");
  expectRoundTrip(kExplicitDepthNames, parseExplicitDepth, "ExplicitDepth");
}

// Three tables are not plain round trips: the volume count is reported as "z-fail" and given as
// "zfail"; "refined" names what a refined GPU volume's draw was, and is no choice; the timing
// method is only ever reported.
TEST(EnumNames, VolumeCountGpuDrawAndTimingKeepTheirOwnSpellings) {
  for (const auto& e : kVolumeCountOptionNames) {
    VolumeCount c = e.value == VolumeCount::Auto ? VolumeCount::ZFail : VolumeCount::Auto;
    ASSERT_TRUE(parseVolumeCount(e.name, c)) << e.name;
    EXPECT_EQ(c, e.value);
    EXPECT_STREQ(toString(c), nameIn(kVolumeCountNames, e.value));
  }
  EXPECT_STREQ(toString(VolumeCount::ZFail), "z-fail");
  VolumeCount c = VolumeCount::Auto;
  EXPECT_FALSE(parseVolumeCount("z-fail", c));

  for (const auto& e : kGpuVolumeDrawNames) {
    EXPECT_STREQ(toString(e.value), e.name);
    GpuVolumeDraw d = GpuVolumeDraw::AllQuads;
    EXPECT_EQ(parseGpuVolumeDraw(e.name, d), e.value != GpuVolumeDraw::Refined) << e.name;
    if (e.value != GpuVolumeDraw::Refined) {
      EXPECT_EQ(d, e.value);
    }
  }
  GpuVolumeDraw d = GpuVolumeDraw::Indexed;
  EXPECT_FALSE(parseGpuVolumeDraw("refined", d));
  EXPECT_EQ(d, GpuVolumeDraw::Indexed);

  EXPECT_STREQ(toString(TimingMethod::GpuTimer), "gpu-timer-query");
  EXPECT_STREQ(toString(TimingMethod::WallClock), "wall-clock-glfinish");
}

TEST(EnumNames, ChoiceListsAndMessagesComeFromTheTables) {
  EXPECT_EQ(namesIn(kCaptureModeNames, {"auto"}),
            (std::vector<std::string>{"auto", "back", "front", "midpoint", "entry"}));
  EXPECT_EQ(namesIn(kGpuVolumeDrawNames, {}, {GpuVolumeDraw::Refined}),
            (std::vector<std::string>{"auto", "indexed", "kept-quads", "compute-mesh", "all-quads"}));
  EXPECT_EQ(choicesText(namesIn(kLightTypeNames), true), "\"spot\", \"directional\" or \"point\"");
  EXPECT_EQ(choicesText(namesIn(kFarCapNames)), "exact or quad");
  EXPECT_EQ(choicesText({"one"}), "one");
  EXPECT_EQ(choicesText({}), "");
  EXPECT_STREQ(nameIn(kFarCapNames, static_cast<FarCap>(7)), "?");
}

}  // namespace
}  // namespace shadowvol
