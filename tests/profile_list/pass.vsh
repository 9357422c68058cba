// vs_2_0: position and texcoord0 passed on through oPos and oT0, color0 through oD0.
vs_2_0
dcl_position v0
dcl_texcoord0 v1
dcl_color0 v2
mov oPos, v0
mov oT0, v1
mov oD0, v2
