// Writing .jsurf: SURFER's keys, a formula SURFER can read, and clear refusals and notes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "jsurf/jsurf.hpp"
#include "jsurf/properties.hpp"
#include "jsurf/read_surfer.hpp"
#include "jsurf/surfer_syntax.hpp"

namespace zs::jsurf {
namespace {

Exported exportOk(const Scene& s) {
  auto r = exportJsurf(s);
  if (auto* err = std::get_if<std::string>(&r)) {
    ADD_FAILURE() << *err;
    return {};
  }
  return std::get<Exported>(r);
}

TEST(JsurfExport, WritesEveryKeySurferReadsAndNothingElse) {
  Scene s;
  s.domain.shape = DomainShape::Sphere;
  const Exported e = exportOk(s);
  std::vector<std::string> keys;
  for (const Property& p : readProperties(e.text)) keys.push_back(p.key);
  for (const std::string& k : surferKeys()) {
    if (k == "transform_matrix") continue;  // SURFER's viewer writes rotation_matrix only
    EXPECT_NE(std::find(keys.begin(), keys.end(), k), keys.end()) << k;
  }
  EXPECT_EQ(keys.size(), surferKeys().size() - 1);
}

TEST(JsurfExport, KeepsTheFormulaTextWhenSurferReadsIt) {
  Scene s;
  s.formula = "x^2 + y^2 - (1 + a)*z^2";
  s.domain.shape = DomainShape::Sphere;
  const Exported e = exportOk(s);
  EXPECT_NE(e.text.find("surface_equation=x^2 + y^2 - (1 + a)*z^2\n"), std::string::npos);
}

TEST(JsurfExport, RewritesImplicitProductsInSurfersSyntax) {
  Scene s;
  s.formula = "2x^2 + 3(y^2 + z^2) = 1";
  s.domain.shape = DomainShape::Sphere;
  const Exported e = exportOk(s);
  const auto props = readProperties(e.text);
  const auto it = std::find_if(props.begin(), props.end(),
                               [](const Property& p) { return p.key == "surface_equation"; });
  ASSERT_NE(it, props.end());
  EXPECT_EQ(checkSurferSyntax(it->value), std::nullopt) << it->value;
  ASSERT_FALSE(e.warnings.empty());
  EXPECT_NE(e.warnings[0].find("SURFER's syntax"), std::string::npos);
}

TEST(JsurfExport, RefusesWhatSurferCannotDraw) {
  Scene s;
  s.formula = "sin(x) + y";
  auto r = exportJsurf(s);
  ASSERT_TRUE(std::holds_alternative<std::string>(r));
  EXPECT_NE(std::get<std::string>(r).find("polynomials"), std::string::npos);
  s.formula = "sinh(a)*x + y";
  r = exportJsurf(s);
  ASSERT_TRUE(std::holds_alternative<std::string>(r));
  EXPECT_NE(std::get<std::string>(r).find("no function 'sinh'"), std::string::npos);
}

TEST(JsurfExport, BoxDomainBecomesTheBallThroughItsCornersWithANote) {
  Scene s;  // the default box [-1.5, 1.5]^3
  const Exported e = exportOk(s);
  ASSERT_FALSE(e.warnings.empty());
  EXPECT_NE(e.warnings[0].find("ball through its corners"), std::string::npos);
  const ImportResult back = importJsurf(e.text, "box.jsurf");
  ASSERT_TRUE(std::holds_alternative<Imported>(back));
  EXPECT_NEAR(std::get<Imported>(back).scene.domain.radius, std::sqrt(3 * 1.5 * 1.5), 1e-12);
}

TEST(JsurfExport, ClipPlanesAreLeftOutWithANote) {
  Scene s;
  s.domain.shape = DomainShape::Sphere;
  s.render.clipPlanes = {{true, {0, 0, 1}, 0.2}, {false, {1, 0, 0}, 0}, {true, {0, 1, 0}, 0}};
  const Exported e = exportOk(s);
  EXPECT_TRUE(std::any_of(e.warnings.begin(), e.warnings.end(), [](const std::string& w) {
    return w.find("2 clip planes are left out") != std::string::npos;
  }));
}

}  // namespace
}  // namespace zs::jsurf
