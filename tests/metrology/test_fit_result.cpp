// Fit<T> value-or-error behaviour and the stable error code names.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "imess/metrology/metrology.hpp"  // the umbrella header must compile on its own

using namespace imess::metrology;

TEST_CASE("Fit<T> holds either a value or an error", "[fit_result]") {
  Fit<int> good(42);
  CHECK(good.ok());
  CHECK(static_cast<bool>(good));
  CHECK(*good == 42);
  CHECK(good.value() == 42);

  Fit<int> bad(FitError{FitErrorCode::CollinearPoints, "plane: the 4 points are collinear"});
  CHECK_FALSE(bad.ok());
  CHECK(bad.error().code == FitErrorCode::CollinearPoints);
  CHECK_THROWS_WITH(bad.value(), Catch::Contains("collinear_points") && Catch::Contains("plane: the 4 points"));
}

TEST_CASE("error codes keep their numbers and have distinct names", "[fit_result]") {
  CHECK(static_cast<int>(FitErrorCode::TooFewPoints) == 1);
  CHECK(static_cast<int>(FitErrorCode::NonPositiveSize) == 10);
  std::set<std::string> names;
  for (int c = 1; c <= 10; ++c) names.insert(std::string(to_string(static_cast<FitErrorCode>(c))));
  CHECK(names.size() == 10);
  CHECK(names.count("unknown") == 0);
  FitStats s;
  s.min_residual = -0.002;
  s.max_residual = 0.003;
  CHECK(s.form() == Approx(0.005));
}
