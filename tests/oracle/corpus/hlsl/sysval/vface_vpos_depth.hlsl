// All three special inputs/outputs at once: VFACE, VPOS and DEPTH.
sampler2D stipple;
float4 colFront, colBack;

float4 main(float face : VFACE, float2 screen : VPOS, float4 hp : TEXCOORD0, out float oDepth : DEPTH) : COLOR
{
    float s = tex2D(stipple, screen / 8).r;
    clip(s - 0.5);
    oDepth = hp.z / hp.w;
    return face > 0 ? colFront : colBack;
}
