// oracle: target=vs_2_a
// vs_2_x shader decompiled by ps30 (HLSL for vs_2_a)
float density : register(c5);
float4 flip : register(c6); // the table's type: bool
float4 highColor : register(c7);
float morph : register(c4);
float4x4 worldViewProj : register(c0);

struct VS_OUTPUT
{
    float4 position0 : POSITION0;
    float4 color0 : COLOR0;
    float fog0 : FOG0;
};

VS_OUTPUT main(float4 position0 : POSITION0, float4 position1 : POSITION1, float4 color0 : COLOR0)
{
    precise float4 oPos = 0, oD0 = 0, oFog = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = morph * (position1 - position0) + position0;
    r0.y = (r0.y * flip.x) * -2.0 + r0.y;
    oPos.w = dot(r0, worldViewProj._m03_m13_m23_m33);
    r1.x = dot(r0, worldViewProj._m02_m12_m22_m32);
    [branch] if (1.0 < r0.y) {
        r1.y = log2(abs((r0.y + 1.0)));
        oD0 = r1.y * highColor;
    } else {
        oD0 = color0;
    }
    oPos.z = r1.x;
    oPos.x = dot(r0, worldViewProj._m00_m10_m20_m30);
    oPos.y = dot(r0, worldViewProj._m01_m11_m21_m31);
    oFog = exp2(((r1.x * r1.x) * -density));
    VS_OUTPUT result;
    result.position0 = oPos;
    result.color0 = oD0;
    result.fog0 = oFog.x;
    return result;
}
