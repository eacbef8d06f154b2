// Seed 003's turn-string simplification on the document's own worked examples.
#include <gtest/gtest.h>

#include "planner/maze/maze_strings.h"

namespace plantsim::planner {
namespace {

TEST(MazeStrings, TheDocumentsWorkedExamples) {
  EXPECT_EQ(simplify_turns("SULLULULL", Hand::kLeft), "RRL");
  EXPECT_EQ(simplify_turns("RRURURRUS", Hand::kRight), "RLL");
  EXPECT_EQ(simplify_turns("SLULULSLULULSLULULL", Hand::kLeft), "SRSRSRL");
}

TEST(MazeStrings, SingleRulesAndNothingToDo) {
  EXPECT_EQ(simplify_turns("SUL", Hand::kLeft), "R");
  EXPECT_EQ(simplify_turns("LUS", Hand::kLeft), "R");
  EXPECT_EQ(simplify_turns("LUL", Hand::kLeft), "S");
  EXPECT_EQ(simplify_turns("SUR", Hand::kRight), "L");
  EXPECT_EQ(simplify_turns("RUR", Hand::kRight), "S");
  EXPECT_EQ(simplify_turns("LSR", Hand::kLeft), "LSR");
  EXPECT_EQ(simplify_turns("", Hand::kRight), "");
  EXPECT_EQ(simplify_turns("SUL", Hand::kRight),
            "SUL");  // left-hand patterns mean nothing to the right hand
}

TEST(MazeStrings, BadLettersAreRefused) {
  EXPECT_THROW(simplify_turns("SXL", Hand::kLeft), std::invalid_argument);
}

}  // namespace
}  // namespace plantsim::planner
