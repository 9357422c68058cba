// Debug overlay: checkerboard from VPOS blended over the scene.
sampler2D scene;
float2 invRes;
float cell = 16;

float4 main(float2 vpos : VPOS) : COLOR
{
    float2 uv = (vpos + 0.5) * invRes;
    float2 k = floor(vpos / cell);
    float check = frac((k.x + k.y) * 0.5) * 2;
    return lerp(tex2D(scene, uv), check, 0.25);
}
