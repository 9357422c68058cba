vs_3_0
// c[a0.x] based at two defs: indices 0 and 1 read their literals (a zero and negative values among them), 2 and up the application's constants; --verify's blendindices reach 0 to 4, draw 1 at quarters
def c0, 1, 0.5, -0.25, 0
def c1, -2, 0, 3, 0.125
dcl_position v0
dcl_blendindices v1
dcl_position o0
dcl_texcoord o1
dcl_texcoord1 o2
mova a0.x, v1.x
mov o1, c[a0.x]
add o2, c[a0.x + 1], v0
mov o0, v0
