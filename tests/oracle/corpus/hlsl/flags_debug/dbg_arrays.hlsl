// oracle: flags=DEBUG|SKIP_OPTIMIZATION
// Debug information for a local array indexed in a loop.
float4 c[3];
float4 main(float4 v : TEXCOORD0) : COLOR
{
    float arr[3];
    for (int i = 0; i < 3; i++)
        arr[i] = dot(v, c[i]);
    float4 m = float4(arr[0], arr[1], arr[2], 1);
    return m;
}
