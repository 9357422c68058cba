// vs_3_0: position, color0 and texcoord0-2 passed on as they arrive from the vertex buffers.
vs_3_0
dcl_position v0
dcl_color0 v1
dcl_texcoord0 v2
dcl_texcoord1 v3
dcl_texcoord2 v4
dcl_position o0
dcl_color0 o1
dcl_texcoord0 o2
dcl_texcoord1 o3
dcl_texcoord2 o4
mov o0, v0
mov o1, v1
mov o2, v2
mov o3, v3
mov o4, v4
