// Globals and a struct whose members shadow global names.
struct Light { float4 color; float4 position; };
float4 color;
float4 position;
Light light;

float4 main(float4 p : TEXCOORD0) : COLOR
{
    return color * light.color + (position - p) * 0.1 + (light.position - p);
}
