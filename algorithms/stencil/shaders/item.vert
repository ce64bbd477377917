#version 330 core
// Primitives in the frame centred on the scene (float positions), each with its item id.
layout(location = 0) in vec3 position;
layout(location = 1) in uint item;
uniform mat4 mvp;
flat out uint v_item;
void main() {
  gl_Position = mvp * vec4(position, 1.0);
  v_item = item;
}
