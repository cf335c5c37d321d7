#pragma once
// The last vertex-processing stage's outputs by the names glTransformFeedbackVaryings takes
// (OpenGL 4.5, 11.1.2.1): "gl_Position", "gl_PointSize", "gl_ClipDistance" or one element of it
// ("gl_ClipDistance[1]"), a variable ("color"), an array element ("weights[2]"), a structure
// member ("s.normal") and a block member by the block's name ("Block.member", not the instance's).
#include <string>
#include <vector>

#include "stages/glsl/glsl_interface.h"
#include "stages/glsl/glsl_program.h"

namespace tessref::glsl {

// Where the rasterizer's vertex holds each word of the output `name` (OutputWords);
// std::invalid_argument saying why when the stage has no such output (GL: the program fails to
// link).
OutputWords output_floats(const StageProgram& last, const VaryingLayout& layout, const std::string& name);

}  // namespace tessref::glsl
