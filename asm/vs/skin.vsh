vs_2_0
// One bone per vertex: blendindices0.x picks the matrix, c[a0.x] its first row.
dcl_position v0
dcl_texcoord0 v1
dcl_blendindices v2
mova a0.x, v2.x
m4x4 oPos, v0, c[a0.x]
mov oT0, v1
