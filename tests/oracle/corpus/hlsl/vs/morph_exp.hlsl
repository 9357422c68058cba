// oracle: target=vs_2_a
// vs_2_a: a morph between two positions, exponential height fog (exp2, log2), a static
// branch on a bool and a dynamic one on the vertex's height.
float4x4 worldViewProj;
float morph;
float density;
bool flip;
float4 highColor;

struct Out
{
    float4 pos : POSITION;
    float4 color : COLOR0;
    float fog : FOG;
};

Out main(float4 p0 : POSITION0, float4 p1 : POSITION1, float4 color : COLOR0)
{
    float4 p = lerp(p0, p1, morph);
    if (flip)
        p.y = -p.y;
    Out o;
    o.pos = mul(p, worldViewProj);
    o.color = color;
    [branch] if (p.y > 1)
        o.color = highColor * log2(1 + p.y);
    o.fog = exp2(-density * o.pos.z * o.pos.z);
    return o;
}
