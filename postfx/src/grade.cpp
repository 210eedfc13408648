// Grades from layered operators, and the presets (grade.hpp).

#include "luxel/postfx/grade.hpp"

#include <glm/common.hpp>
#include <glm/exponential.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

namespace luxel::postfx {

namespace {

glm::vec3 saturate(glm::vec3 c) { return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f)); }

/// Fritsch-Carlson tangents: the cubic Hermite through the points is monotone wherever the
/// points are.
std::vector<float> monotone_tangents(const std::vector<glm::vec2>& p) {
  const size_t n = p.size();
  std::vector<float> secant(n - 1), m(n);
  for (size_t k = 0; k + 1 < n; ++k) secant[k] = (p[k + 1].y - p[k].y) / (p[k + 1].x - p[k].x);
  m[0] = secant[0];
  m[n - 1] = secant[n - 2];
  for (size_t k = 1; k + 1 < n; ++k) m[k] = secant[k - 1] * secant[k] <= 0.0f ? 0.0f : (secant[k - 1] + secant[k]) / 2.0f;
  for (size_t k = 0; k + 1 < n; ++k) {
    if (secant[k] == 0.0f) {
      m[k] = m[k + 1] = 0.0f;
      continue;
    }
    const float a = m[k] / secant[k], b = m[k + 1] / secant[k];
    const float r = a * a + b * b;
    if (r > 9.0f) {
      const float t = 3.0f / std::sqrt(r);
      m[k] = t * a * secant[k];
      m[k + 1] = t * b * secant[k];
    }
  }
  return m;
}

bool finite(std::initializer_list<float> values) {
  return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

void check_curve(const Curve& c, const char* which) {
  if (c.points.empty()) return;
  auto fail = [&](const std::string& why) { throw std::invalid_argument(std::string("curves: ") + which + " curve " + why); };
  if (c.points.size() < 2) fail("needs at least two points");
  for (size_t k = 0; k < c.points.size(); ++k) {
    const glm::vec2 q = c.points[k];
    if (!(q.x >= 0.0f && q.x <= 1.0f && q.y >= 0.0f && q.y <= 1.0f)) fail("has a point outside [0, 1]");
    if (k > 0 && !(q.x > c.points[k - 1].x)) fail("needs strictly increasing x");
  }
}

void check(const GradeOperator& op) {
  if (const auto* c = std::get_if<Curves>(&op)) {
    check_curve(c->master, "master");
    check_curve(c->red, "red");
    check_curve(c->green, "green");
    check_curve(c->blue, "blue");
  } else if (const auto* l = std::get_if<Levels>(&op)) {
    if (!finite({l->in_black, l->in_white, l->gamma, l->out_black, l->out_white})) {
      throw std::invalid_argument("levels: every value must be finite");
    }
    if (!(l->in_black < l->in_white)) throw std::invalid_argument("levels: in_black must be below in_white");
    if (!(l->gamma > 0.0f)) throw std::invalid_argument("levels: gamma must be above 0");
  } else if (const auto* b = std::get_if<ColorBalance>(&op)) {
    const glm::vec3 o[3] = {b->shadows, b->midtones, b->highlights};
    for (const glm::vec3& v : o)
      if (!finite({v.x, v.y, v.z})) throw std::invalid_argument("color balance: every offset must be finite");
  } else if (const auto* s = std::get_if<Saturation>(&op)) {
    if (!(s->amount >= 0.0f) || !std::isfinite(s->amount)) throw std::invalid_argument("saturation: amount must be 0 or more");
  }
}

struct ApplyOperator {
  glm::vec3 c;
  glm::vec3 operator()(const Curves& k) const {
    const glm::vec3 m(k.master(c.x), k.master(c.y), k.master(c.z));
    return glm::vec3(k.red(m.x), k.green(m.y), k.blue(m.z));
  }
  glm::vec3 operator()(const Levels& l) const {
    const glm::vec3 t = saturate((c - l.in_black) / (l.in_white - l.in_black));
    return l.out_black + (l.out_white - l.out_black) * glm::pow(t, glm::vec3(1.0f / l.gamma));
  }
  glm::vec3 operator()(const ColorBalance& b) const {
    const float L = grade_luma(c);
    return c + b.shadows * ((1.0f - L) * (1.0f - L)) + b.midtones * (2.0f * L * (1.0f - L)) + b.highlights * (L * L);
  }
  glm::vec3 operator()(const Saturation& s) const {
    const float L = grade_luma(c);
    return glm::vec3(L) + s.amount * (c - glm::vec3(L));
  }
};

}  // namespace

float Curve::operator()(float x) const {
  if (points.empty()) return x;
  if (x <= points.front().x) return points.front().y;
  if (x >= points.back().x) return points.back().y;
  const std::vector<float> m = monotone_tangents(points);
  size_t k = 0;
  while (x > points[k + 1].x) ++k;
  const float h = points[k + 1].x - points[k].x, t = (x - points[k].x) / h;
  const float t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * points[k].y + (t3 - 2 * t2 + t) * h * m[k] + (-2 * t3 + 3 * t2) * points[k + 1].y +
         (t3 - t2) * h * m[k + 1];
}

float grade_luma(glm::vec3 c) { return 0.299f * c.x + 0.587f * c.y + 0.114f * c.z; }

glm::vec3 apply_grade(const Grade& grade, glm::vec3 color) {
  glm::vec3 c = saturate(color);
  for (const GradeOperator& op : grade.operators) c = saturate(std::visit(ApplyOperator{c}, op));
  return c;
}

ColorTransform grade_transform(Grade grade, std::string name) {
  std::string description = "grade:";
  static const char* kNames[] = {"curves", "levels", "color balance", "saturation"};
  for (const GradeOperator& op : grade.operators) {
    check(op);
    description += std::string(description.back() == ':' ? " " : ", ") + kNames[op.index()];
  }
  if (grade.operators.empty()) description += " identity";
  return {std::move(name), std::move(description), [grade = std::move(grade)](std::span<glm::vec3> colors) {
            for (glm::vec3& c : colors) c = apply_grade(grade, c);
          }};
}

const std::vector<std::string>& grade_preset_names() {
  static const std::vector<std::string> names = {"day-for-night", "archival", "warm", "cool"};
  return names;
}

std::optional<Grade> grade_preset(std::string_view name) {
  if (name == "day-for-night") {
    // Shot by day, shown as night: most color gone, a blue cast strongest in the shadows and
    // midtones, then white brought down to 0.3 with the midtones pulled lower still.
    return Grade{{Saturation{0.4f},
                  ColorBalance{{-0.02f, 0.0f, 0.05f}, {-0.06f, -0.01f, 0.08f}, {-0.08f, -0.02f, 0.04f}},
                  Levels{0.0f, 1.0f, 0.85f, 0.0f, 0.3f}}};
  }
  if (name == "archival") {
    // Old footage: nearly grey, blacks and whites faded toward the middle, warmed like aged stock.
    return Grade{{Saturation{0.1f},
                  Curves{Curve{{{0.0f, 0.08f}, {0.25f, 0.26f}, {0.75f, 0.78f}, {1.0f, 0.92f}}}, {}, {}, {}},
                  ColorBalance{{0.0f, 0.0f, 0.0f}, {0.03f, 0.01f, -0.03f}, {0.02f, 0.01f, -0.02f}}}};
  }
  if (name == "warm") {
    return Grade{{ColorBalance{{0.02f, 0.0f, -0.02f}, {0.06f, 0.02f, -0.05f}, {0.03f, 0.01f, -0.03f}}}};
  }
  if (name == "cool") {
    return Grade{{ColorBalance{{-0.02f, 0.0f, 0.02f}, {-0.05f, 0.01f, 0.06f}, {-0.03f, 0.0f, 0.03f}}}};
  }
  return std::nullopt;
}

}  // namespace luxel::postfx
