// oracle: target=vs_2_0
// A waving flag: the position displaced by sin and cos of a phase made of time and the
// vertex's x, and the point size for a particle view.
float4x4 worldViewProj;
float4 wave;
float time;

struct Out
{
    float4 pos : POSITION;
    float4 color : COLOR0;
    float size : PSIZE;
};

Out main(float4 pos : POSITION, float4 color : COLOR0)
{
    float phase = pos.x * wave.x + time * wave.y;
    float s, c;
    sincos(phase, s, c);
    float4 p = pos;
    p.y += s * wave.z;
    p.z += c * wave.w;
    Out o;
    o.pos = mul(p, worldViewProj);
    o.color = color * (0.75 + 0.25 * c);
    o.size = 4 + 2 * s;
    return o;
}
