// Input and output structs with a nested helper struct.
struct Surface { float3 albedo; float3 normal; float alpha; };
struct PSInput
{
    float4 color    : COLOR0;
    float2 uv       : TEXCOORD0;
    float3 normalWS : TEXCOORD1;
};
struct PSOutput
{
    float4 color : COLOR0;
    float4 extra : COLOR1;
};

sampler2D main_tex;
float3 light_dir;

Surface GetSurface(PSInput i)
{
    Surface s;
    float4 t = tex2D(main_tex, i.uv) * i.color;
    s.albedo = t.rgb;
    s.alpha = t.a;
    s.normal = normalize(i.normalWS);
    return s;
}

PSOutput main(PSInput input)
{
    Surface s = GetSurface(input);
    PSOutput o;
    o.color = float4(s.albedo * saturate(dot(s.normal, light_dir)), s.alpha);
    o.extra = float4(s.normal * 0.5 + 0.5, 1);
    return o;
}
