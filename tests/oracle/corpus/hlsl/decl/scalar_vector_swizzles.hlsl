// Swizzle-heavy code: replicate, reorder, write masks, constant folding.
float4 a, b;

float4 main(float4 v : TEXCOORD0) : COLOR
{
    float4 r;
    r.xy = v.yx * a.ww;
    r.zw = v.zz + b.xy;
    r.x += dot(v.xyz, a.zyx);
    r = r.wzyx * 0.5 + r.xxyy;
    r.yz = max(r.yz, a.wx);
    return r;
}
