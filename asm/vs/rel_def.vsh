vs_2_0
// c[a0.x] based at two defs: indices 0 and 1 read their literals (a zero and negative values among them), 2 and up the application's constants; --verify's blendindices reach 0 to 4, draw 1 at quarters
def c0, 1, 0.5, -0.25, 0
def c1, -2, 0, 3, 0.125
dcl_position v0
dcl_blendindices v1
mova a0.x, v1.x
mov oT0, c[a0.x]
add oT1, c[a0.x + 1], v0
mov oPos, v0
