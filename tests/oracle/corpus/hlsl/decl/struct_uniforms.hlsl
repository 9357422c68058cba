// Uniform structs, nested, with arrays inside: the constant table lists members.
struct Material
{
    float4 diffuse;
    float4 specular;
    float  power;
};
struct Fog { float3 color; float start; float end; };
struct Scene
{
    Material mat;
    Fog fog;
    float4 lights[2];
};
Scene scene;

float4 main(float3 n : TEXCOORD0, float dist : TEXCOORD1) : COLOR
{
    float3 N = normalize(n);
    float4 c = 0;
    for (int i = 0; i < 2; i++)
        c += scene.mat.diffuse * saturate(dot(N, scene.lights[i].xyz));
    c += scene.mat.specular * pow(saturate(N.z), scene.mat.power);
    float f = saturate((dist - scene.fog.start) / (scene.fog.end - scene.fog.start));
    return float4(lerp(c.rgb, scene.fog.color, f), c.a);
}
