#version 450 core
// One colour for the whole draw, in each of four draw buffers (an output a draw buffer gets no
// value from is undefined in GL).
uniform vec4 u_fill;
layout(location = 0) out vec4 out_0;
layout(location = 1) out vec4 out_1;
layout(location = 2) out vec4 out_2;
layout(location = 3) out vec4 out_3;

void main() {
  out_0 = u_fill;
  out_1 = u_fill;
  out_2 = u_fill * 3.0 - 1.0;
  out_3 = u_fill.zyxw;
}
