#version 330 core
// The colour buffer holds item id + 1 (0: no primitive).
flat in uint v_item;
layout(location = 0) out uint colour;
void main() { colour = v_item + 1u; }
