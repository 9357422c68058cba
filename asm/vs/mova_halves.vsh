vs_2_0
// mova at exact halves (0.5, 1.5, 2.5 and -0.5, -1.5 from literals): which register each reads
def c0, 0.5, 1.5, 2.5, 0
dcl_position v0
mova a0.x, c0.x
mov oT0, c[a0.x + 9]
mova a0.x, c0.y
mov oT1, c[a0.x + 9]
mova a0.x, c0.z
mov oT2, c[a0.x + 9]
mova a0.x, -c0.x
mov oT3, c[a0.x + 11]
mova a0.x, -c0.y
mov oT4, c[a0.x + 11]
mov oPos, v0
