// oracle: target=ps_2_0
// A sprite that writes its own depth: a soft particle's colour faded by its distance to
// the scene depth, and DEPTH offset by the sprite's sphere.
sampler2D sprite : register(s0);
sampler2D sceneDepth : register(s1);
float fadeScale;

void main(float2 uv : TEXCOORD0, float4 screen : TEXCOORD1, float4 tint : COLOR0,
          out float4 color : COLOR0, out float depth : DEPTH)
{
    float4 s = tex2D(sprite, uv);
    float scene = tex2Dproj(sceneDepth, screen).r;
    float2 d = uv * 2 - 1;
    float bulge = sqrt(saturate(1 - dot(d, d)));
    float z = screen.z / screen.w - bulge * 0.01;
    color = s * tint * saturate((scene - z) * fadeScale);
    depth = z;
}
