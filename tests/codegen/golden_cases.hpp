#pragma once
// The formulas of the golden tests (tests/golden/<name>.glsl): the 7 surfaces of the
// thesis' Table 5.1 and edge cases of the emitter. The semantics test runs them too.
namespace zs::test {

struct GoldenCase {
  const char* name;
  const char* formula;
};

// Thesis Table 5.1, surfaces 1-7.
inline constexpr GoldenCase kThesis[] = {
    {"thesis1_paraboloid", "x^2+z^2-y"},
    {"thesis2_symmetric_cubic", "x^2*y+x^2*z+y^2*x+y^2*z+z^2*y+z^2*x-(2/5)*(x*y+x*z+y*z)"},
    {"thesis3_cuboid", "x^4+y^4+z^4-1"},
    {"thesis4_mixed_degrees", "x^2+y^3+z^5-1"},
    {"thesis5_klein_quartic", "x^3*y+y^3*z+z^3*x"},
    {"thesis6_quartic_saddle", "x^4-z^4-y"},
    {"thesis7_quartic_cross", "x^2*y^2+y^2*z^2+z^2*x^2-1"},
};

inline constexpr GoldenCase kEdgeCases[] = {
    {"edge_parameters", "a*x^2 + b*y^2 + c*z^2 - radius^2 + alpha sin(beta x)"},
    {"edge_trig", "sin(x) + cos(y) + tan(z) + asin(x/2) + acos(y/2) + atan(z)"},
    {"edge_hyperbolic_exp_log", "atan2(y, x) + sinh(x) + cosh(y) + tanh(z) + exp(x) + log(y^2+1)"},
    {"edge_roots_abs_rounding",
     "sqrt(x^2+y^2) + cbrt(z) + abs(x) + sign(y) + floor(z) + ceil(x) - 1"},
    {"edge_min_max_pow", "min(x, y) + max(y, z) + pow(x^2+1, y) + pow(z, 3) - 1"},
    {"edge_real_exponents", "x^2.5 + abs(y)^0.5 + z^(1/3) + (x^2+1)^-1.5 - 1"},
    {"edge_large_exponents", "x^1024 + y^-7 + z^13 + (x+y)^1000 - 1"},
    {"edge_tiny_huge_constants",
     "1e-50*x + 1e300*y + 3.4028236e38*z + 1e-45 - 2.5e-38 + 123456789.123456789"},
    {"edge_deep_nesting",
     "sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(x+y))))))))))))))))"
     " + ((((((((((z+1)*x+2)*y+3)*z+4)*x+5)*y+6)*z+7)*x+8)*y+9)*z) - 1"},
    {"edge_shared_subexpressions", "(x^2+y^2+z^2)^2 - (x^2+y^2+z^2) + sin(x^2+y^2+z^2)"},
    {"edge_implicit_multiplication", "2x y + (x+1)(y-1) - 2 pi z + [x - z]^2 e"},
    {"edge_division", "1/x + y/(z^2+1) - x/(y - 1) + (x^2 - 1)/(x - 1)"},
    {"edge_constant_root", "x = 1"},
    {"edge_constant_surface", "2 = 1"},
    {"edge_undefined_everywhere", "sqrt(-1) + x"},
    {"edge_gradient_only_domain", "pow(x, y) - z"},
    {"edge_gyroid", "sin(x)cos(y) + sin(y)cos(z) + sin(z)cos(x)"},
};

// The interval block (tests/golden/interval_<name>.glsl): every rule of
// op_interval_glsl.cpp at least once, domain flags, NaN and out-of-float constants.
inline constexpr GoldenCase kIntervalCases[] = {
    {"gyroid", "sin(x)cos(y) + sin(y)cos(z) + sin(z)cos(x)"},
    {"metaballs",
     "exp(-4((x-0.5)^2+y^2+z^2)) + exp(-4((x+0.5)^2+y^2+z^2)) + exp(-4(x^2+(y-0.7)^2+z^2)) - 0.6"},
    {"bumpy_sphere", "sqrt(x^2+y^2+z^2) - 1 - 0.08 sin(10x) sin(10y) sin(10z)"},
    {"poles_and_domains", "1/x - 1 + sqrt(y) + log(z^2) + asin(x/2) + acos(y/2) + tan(z)"},
    {"other_rules",
     "atan(x) + atan2(y, x) + sinh(x) + cosh(y) + tanh(z) + cbrt(z) + abs(x) "
     "+ sign(y) + floor(z) + ceil(x) + min(x, y) + max(y, z) + pow(x^2+1, y) "
     "+ x^2.5 + y^-3 + z^6 - 1"},
    {"constants", "0.1 x + 1e300 y + 1e-45 z - a + sqrt(-1) * 0"},
};

}  // namespace zs::test
