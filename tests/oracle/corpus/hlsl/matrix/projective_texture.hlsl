// Projector: texture coordinates from a uniform matrix, with back-projection rejected.
sampler2D projTex;
float4x4 projectorViewProj;

float4 main(float4 wpos : TEXCOORD0) : COLOR
{
    float4 pc = mul(wpos, projectorViewProj);
    float4 t = pc * float4(0.5, -0.5, 1, 1) + float4(0.5, 0.5, 0, 0) * pc.w;
    float front = pc.w > 0;
    return tex2Dproj(projTex, t) * front;
}
