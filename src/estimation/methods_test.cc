#include "hecal/estimation/methods.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace hecal::estimation {
namespace {

// The CLI names in the order of `--method all` (docs/cli.md#methods).
const std::vector<std::string> kCliNames = {
    "tsai-lenz",  "park-martin", "horaud",  "horaud-nonlinear",
    "chou-kamel", "daniilidis",  "andreff", "shiu-ahmad",
    "shah",       "li",          "strobl",  "ml"};

TEST(Methods, NamesAreTheCliNamesInOrderAndRoundTrip) {
  std::vector<std::string> names;
  for (const MethodInfo& info : AllMethods()) {
    EXPECT_EQ(info.method, static_cast<Method>(names.size())) << info.name;
    EXPECT_EQ(ParseMethod(info.name), info.method);
    EXPECT_EQ(&Info(info.method), &info);
    EXPECT_GT(info.summary.size(), 40u) << info.name;
    EXPECT_EQ(info.summary.find('\n'), std::string_view::npos) << info.name;
    names.emplace_back(info.name);
  }
  EXPECT_EQ(names, kCliNames);
  EXPECT_THROW(Info(static_cast<Method>(kCliNames.size())), std::invalid_argument);
}

TEST(Methods, ParseAcceptsExactNamesOnly) {
  EXPECT_EQ(ParseMethod("ml"), Method::kMl);
  EXPECT_EQ(ParseMethod("horaud-nonlinear"), Method::kHoraudNonlinear);
  for (const char* text : {"tsai", "", "Park-Martin", " ml", "all", "global"}) {
    EXPECT_FALSE(ParseMethod(text).has_value()) << "'" << text << "'";
  }
}

// Every closed form of the handeye layer is exactly one method here, under its own name and
// summary; the refinements are not closed forms.
TEST(Methods, EveryClosedFormOnceUnderItsHandeyeNameAndTheRefinementsNone) {
  std::vector<handeye::ClosedForm> forms;
  for (const MethodInfo& info : AllMethods()) {
    const bool refinement = info.method == Method::kStrobl || info.method == Method::kMl;
    ASSERT_EQ(info.closed_form.has_value(), !refinement) << info.name;
    if (refinement) continue;
    const handeye::ClosedFormInfo& form = handeye::Info(*info.closed_form);
    EXPECT_EQ(form.name, info.name);
    EXPECT_EQ(form.summary, info.summary);
    forms.push_back(*info.closed_form);
  }
  std::vector<handeye::ClosedForm> expected;
  for (const handeye::ClosedFormInfo& form : handeye::ClosedForms()) expected.push_back(form.form);
  EXPECT_EQ(forms, expected);
}

// Only ml has its own information matrix (ml.h); the others propagate through the solver.
TEST(Methods, OnlyMlHasAnAnalyticCovariance) {
  for (const MethodInfo& info : AllMethods()) {
    EXPECT_EQ(info.analytic_covariance, info.method == Method::kMl) << info.name;
  }
}

}  // namespace
}  // namespace hecal::estimation
