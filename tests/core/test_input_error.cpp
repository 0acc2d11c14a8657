// InputError's ${field} marks (error.h): the library's own problems name other fields, a front
// end spells them its own way; user text (paths, values) is never read for marks.
#include <gtest/gtest.h>

#include <string>

#include "shadowvol/error.h"

namespace shadowvol {
namespace {

std::string bracketed(std::string_view f) { return std::string("[").append(f).append("]"); }

TEST(InputError, FieldMarksShowTheLibraryNameUnlessAFrontEndNamesThem) {
  const InputError e("volume options", "refine chords", "",
                     MarkedProblem{"needs refinement (${refine steps} of at least 1)"});
  EXPECT_TRUE(e.hasFieldMarks());
  EXPECT_EQ(e.problem(), "needs refinement (refine steps of at least 1)");
  EXPECT_STREQ(e.what(), "volume options: refine chords: needs refinement (refine steps of at least 1)");
  EXPECT_EQ(e.problemNamed(bracketed), "needs refinement ([refine steps] of at least 1)");
  EXPECT_EQ(e.problemTemplate(), "needs refinement (${refine steps} of at least 1)");
  const InputError member("RenderOptions", "volume", "gpu", MarkedProblem{"set ${refineCrossings} or ${volumeOptions.bias}"});
  EXPECT_EQ(member.problem(), "set refineCrossings or volumeOptions.bias");
  // In the library's own text, what is not a mark (a lower-case letter first) stays as it is.
  for (const std::string text : {"${HOME}", "unclosed ${refine", "${} empty", "${ x}"}) {
    const InputError odd("file", "", "", MarkedProblem{text});
    EXPECT_EQ(odd.problem(), text);
    EXPECT_EQ(odd.problemNamed(bracketed), text);
  }
  EXPECT_EQ(InputError("f", "", "", MarkedProblem{"${a}${Path}"}).problemNamed(bracketed), "[a]${Path}");
  EXPECT_EQ(InputError("f", "", "", MarkedProblem{"$${b}"}).problemNamed(bracketed), "$[b]");
}

// A second reader's finding: every problem was read for marks, so a path holding "${mesh}" was
// shown as "mesh", and on the command line "${out}" became the flag "--out".
TEST(InputError, UserTextIsNeverReadForMarks) {
  for (const std::string text : {"cannot open m/${mesh}/bad.obj", "the folder nowhere/${out} does not exist",
                                 "${a}${b}", "$${x}"}) {
    const InputError e("file", "/objects/0/file", "m/${mesh}/bad.obj", text);
    EXPECT_FALSE(e.hasFieldMarks());
    EXPECT_EQ(e.problem(), text);
    EXPECT_EQ(e.problemNamed(bracketed), text);
    EXPECT_EQ(std::string(e.what()), "file: /objects/0/file = m/${mesh}/bad.obj: " + text);
  }
}

}  // namespace
}  // namespace shadowvol
