// vs_2_0: position passed on, white through oD0, color1 through oD1 (the
// specular colour, whose alpha vertex fog reads when oFog is not written).
vs_2_0
def c0, 1, 1, 1, 1
dcl_position v0
dcl_color1 v1
mov oPos, v0
mov oD0, c0
mov oD1, v1
