float4 main(float2 uv : TEXCOORD0, float vf : VFACE, float2 vp : VPOS) : COLOR { return vf > 0 ? uv.xyxy : vp.xyxy; }
