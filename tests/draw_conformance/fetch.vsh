// Vertex texture fetch: texldl reads s0 at texcoord0 (LOD 0); the texel is
// the colour passed on, and its alpha moves the position right in clip x.
vs_3_0
dcl_position v0
dcl_texcoord0 v1
dcl_position o0
dcl_texcoord0 o1
dcl_2d s0
texldl r0, v1, s0
mov o0, v0
add o0.x, v0.x, r0.w
mov o1, r0
