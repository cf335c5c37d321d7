// The source-level trace (shader/source_trace.h): one lane's executed lines, loops as executed,
// the values each line computed and stored, and no change to what the batch computes.
#include <gtest/gtest.h>

#include "shader/source_trace.h"
#include "shader_test_util.h"

namespace tessref::shader {
namespace {

using test::Kernel;

// Line numbers matter below: line 1 is #version.
const char* kLoop = R"(#version 450
layout(location = 0) in float a;
layout(location = 0) out vec3 result;
void main() {
  vec3 s = vec3(0.0);
  for (int i = 0; i < 3; ++i) {
    s += vec3(a * float(i), 1.0, 2.0);
  }
  if (a > 2.0) {
    s.y = -s.y;
  }
  result = s;
  gl_Position = vec4(s, 1.0);
}
)";

std::vector<const TraceLine*> executions(const SourceTrace& t, int line) {
  std::vector<const TraceLine*> out;
  for (const TraceLine& l : t.lines)
    if (l.line == line) out.push_back(&l);
  return out;
}

TEST(SourceTrace, LoopsAreUnrolledAsExecutedWithEachIterationsValue) {
  Kernel k(kLoop);
  const float inputs[4] = {0.5f, 1.5f, 2.5f, 3.5f};
  k.begin(4);
  for (int l = 0; l < 4; ++l) k.set_f32("a", l, 0, inputs[l]);
  SourceTrace trace;
  trace.lane = 2;
  {
    SourceTraceScope scope(trace);
    k.run();
  }
  // Line 7 ran once per iteration; its value is that iteration's sum, for lane 2 (a = 2.5) alone.
  const auto body = executions(trace, 7);
  ASSERT_EQ(body.size(), 3u);
  EXPECT_EQ(body[0]->result.text(), "(0, 1, 2)");
  EXPECT_EQ(body[1]->result.text(), "(2.5, 2, 4)");
  EXPECT_EQ(body[2]->result.text(), "(7.5, 3, 6)");
  // The branch lane 2 takes (a > 2) ran, and its store is named with its component.
  const auto flip = executions(trace, 10);
  ASSERT_EQ(flip.size(), 1u);
  EXPECT_EQ(flip[0]->result.text(), "-3");
  const auto out = executions(trace, 12);
  ASSERT_EQ(out.size(), 1u);
  ASSERT_EQ(out[0]->stores.size(), 1u);
  EXPECT_EQ(out[0]->stores[0].target, "result");
  EXPECT_EQ(out[0]->stores[0].value.text(), "(7.5, -3, 6)");
  const auto pos = executions(trace, 13);
  ASSERT_EQ(pos.size(), 1u);
  ASSERT_EQ(pos[0]->stores.size(), 1u);
  EXPECT_EQ(pos[0]->stores[0].target, "gl_Position");  // a member of the unnamed gl_PerVertex block
  EXPECT_EQ(pos[0]->stores[0].value.text(), "(7.5, -3, 6, 1)");
  // The lines come in execution order: the loop's body before the branch, the branch before the
  // output.
  EXPECT_LT(body.back(), flip[0]);
  EXPECT_LT(flip[0], out[0]);
  EXPECT_EQ(trace.dropped, 0u);
}

TEST(SourceTrace, BranchesTheLaneDidNotTakeAreAbsentAndResultsAreUnchanged) {
  Kernel k(kLoop);
  auto run = [&](SourceTrace* trace) {
    k.begin(4);
    for (int l = 0; l < 4; ++l) k.set_f32("a", l, 0, 0.5f + float(l));
    if (trace) {
      SourceTraceScope scope(*trace);
      k.run();
    } else {
      k.run();
    }
    std::vector<std::uint32_t> all;
    for (int l = 0; l < 4; ++l) {
      const auto v = k.value("result", l);
      all.insert(all.end(), v.begin(), v.end());
    }
    return all;
  };
  const auto plain = run(nullptr);
  SourceTrace trace;
  trace.lane = 0;  // a = 0.5: the branch is not taken
  EXPECT_EQ(run(&trace), plain);
  EXPECT_TRUE(executions(trace, 10).empty());
  EXPECT_EQ(executions(trace, 7).size(), 3u);
  EXPECT_EQ(executions(trace, 12).at(0)->stores.at(0).value.text(), "(1.5, 3, 6)");  // 0.5 * (0 + 1 + 2)
}

// `mid = c ? h : f(h);` keeps mid as an SSA value (no store): the line shows the value mid takes
// where the paths meet, after the lines of the inlined f on the path that called it (issue 24).
TEST(SourceTrace, SelectionsShowTheValueWhereTheirPathsMeet) {
  Kernel k(R"(#version 450
layout(location = 0) in vec3 h;
layout(location = 0) out vec3 result;
vec3 safe_normalize(vec3 v) {
  float len = length(v);
  return len > 0.0 ? v / len : vec3(0.0);
}
void main() {
  vec3 mid = h;
  if (h.x > -10.0) {
    mid = h.z > 1.0 ? h : safe_normalize(h);
  }
  result = mid * 2.0;
}
)");
  auto trace_lane = [&](int lane) {
    k.begin(2);
    const float inputs[2][3] = {{3.0f, 0.0f, 4.0f}, {3.0f, 0.0f, -4.0f}};
    for (int l = 0; l < 2; ++l)
      for (int c = 0; c < 3; ++c) k.set_f32("h", l, c, inputs[l][c]);
    SourceTrace trace;
    trace.lane = lane;
    {
      SourceTraceScope scope(trace);
      k.run();
    }
    return trace;
  };
  // Lane 0 (h.z = 4 > 1): mid = h; the callee never ran.
  const SourceTrace taken = trace_lane(0);
  const auto line = executions(taken, 11);
  ASSERT_EQ(line.size(), 1u);
  ASSERT_FALSE(line[0]->joins.empty());
  EXPECT_EQ(line[0]->joins.back().text(), "(3, 0, 4)");
  EXPECT_TRUE(executions(taken, 5).empty());
  // Lane 1: mid = h / 5 through safe_normalize's lines; line 11 comes back with mid's value.
  const SourceTrace called = trace_lane(1);
  const auto again = executions(called, 11);
  ASSERT_EQ(again.size(), 2u);
  EXPECT_TRUE(again[0]->joins.empty());
  ASSERT_FALSE(again[1]->joins.empty());
  EXPECT_EQ(again[1]->joins.back().text(), "(0.600000024, 0, -0.800000012)");
  const auto callee = executions(called, 5);
  ASSERT_EQ(callee.size(), 1u);
  EXPECT_LT(again[0], callee[0]);
  EXPECT_LT(callee[0], again[1]);
  EXPECT_EQ(k.f32("result", 1, 2), -1.6f);
}

TEST(SourceTrace, KeepsAtMostMaxLinesAndCountsTheRest) {
  Kernel k(R"(#version 450
layout(location = 0) in float a;
layout(location = 0) out float result;
void main() {
  float s = 0.0;
  for (int i = 0; i < 1000; ++i)
    s += a;
  result = s;
}
)");
  k.begin(1);
  k.set_f32("a", 0, 0, 1.0f);
  SourceTrace trace;
  trace.max_lines = 50;
  {
    SourceTraceScope scope(trace);
    k.run();
  }
  EXPECT_EQ(trace.lines.size(), 50u);
  EXPECT_GT(trace.dropped, 1000u);  // every later line execution (loop heads included) is counted
  EXPECT_EQ(k.f32("result", 0), 1000.0f);
}

TEST(SourceTrace, AccessPathsNameMembersElementsAndComponents) {
  Kernel k(R"(#version 450
layout(binding = 0) uniform Light { vec3 position; float power[2]; } light;
layout(location = 0) out vec4 result;
void main() {
  result = vec4(light.position, light.power[1]);
}
)");
  const Module& m = k.module();
  // The block's type, found by its member's name.
  std::uint32_t light = 0;
  for (const auto& [key, name] : m.member_names)
    if (name == "power") light = key.first;
  ASSERT_NE(light, 0u);
  EXPECT_EQ(access_path(m, light, 0, 3), ".position");
  EXPECT_EQ(access_path(m, light, 1, 1), ".position.y");
  EXPECT_EQ(access_path(m, light, 4, 1), ".power[1]");
  EXPECT_EQ(access_path(m, light, 0, 5), "");
}

}  // namespace
}  // namespace tessref::shader
