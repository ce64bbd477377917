#version 450 core
// Draw pass: faces projected with the view-projection matrix in double.
layout(location = 0) in dvec3 pos;
layout(location = 1) in int tag;
uniform dmat4 mvp;
flat out int vtag;
void main() {
  gl_Position = vec4(mvp * dvec4(pos, 1.0));
  vtag = tag;
}
