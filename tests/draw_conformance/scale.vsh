// vs_3_0: position scaled componentwise by c0, texcoord0 passed on.
vs_3_0
dcl_position v0
dcl_texcoord0 v1
dcl_position o0
dcl_texcoord0 o1
mul o0, v0, c0
mov o1, v1
