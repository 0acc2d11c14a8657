// InputError's ${field} marks (error.h): the library's problems name other fields, a front end
// spells them its own way.
#include <gtest/gtest.h>

#include <string>

#include "shadowvol/error.h"

namespace shadowvol {
namespace {

TEST(InputError, FieldMarksShowTheLibraryNameUnlessAFrontEndNamesThem) {
  const InputError e("volume options", "refine chords", "", "needs refinement (${refine steps} of at least 1)");
  EXPECT_EQ(e.problem(), "needs refinement (refine steps of at least 1)");
  EXPECT_STREQ(e.what(), "volume options: refine chords: needs refinement (refine steps of at least 1)");
  EXPECT_EQ(e.problemNamed([](std::string_view f) { return std::string("<").append(f).append(">"); }),
            "needs refinement (<refine steps> of at least 1)");
  EXPECT_EQ(e.problemTemplate(), "needs refinement (${refine steps} of at least 1)");
  const InputError member("RenderOptions", "volume", "gpu", "set ${refineCrossings} or ${volumeOptions.bias}");
  EXPECT_EQ(member.problem(), "set refineCrossings or volumeOptions.bias");
}

TEST(InputError, TextThatOnlyLooksLikeAMarkIsKept) {
  // A path or a value in a problem may hold "${": only field names (a lower-case letter first) are marks.
  for (const std::string text : {"cannot open ${HOME}/a.ply", "unclosed ${refine", "${} empty", "${ x}",
                                 "${a}${Path}", "$${b}"}) {
    const InputError e("file", "", "", text);
    const std::string named = e.problemNamed([](std::string_view f) { return std::string("[").append(f).append("]"); });
    if (text == "${a}${Path}") {
      EXPECT_EQ(named, "[a]${Path}");
    } else if (text == "$${b}") {
      EXPECT_EQ(named, "$[b]");
    } else {
      EXPECT_EQ(e.problem(), text);
      EXPECT_EQ(named, text);
    }
  }
}

}  // namespace
}  // namespace shadowvol
