// ps_3_0 shader decompiled by ps30
float4 SampleOffsetsWeights[13] : register(c0);
sampler2D Source : register(s0);

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0;
    r0 = tex2D(Source, (SampleOffsetsWeights[1].xy + texcoord0.xy));
    r0 = SampleOffsetsWeights[0].z * tex2D(Source, (SampleOffsetsWeights[0].xy + texcoord0.xy)) + (r0 * SampleOffsetsWeights[1].z);
    r0 = SampleOffsetsWeights[2].z * tex2D(Source, (SampleOffsetsWeights[2].xy + texcoord0.xy)) + r0;
    r0 = SampleOffsetsWeights[3].z * tex2D(Source, (SampleOffsetsWeights[3].xy + texcoord0.xy)) + r0;
    r0 = SampleOffsetsWeights[4].z * tex2D(Source, (SampleOffsetsWeights[4].xy + texcoord0.xy)) + r0;
    r0 = SampleOffsetsWeights[5].z * tex2D(Source, (SampleOffsetsWeights[5].xy + texcoord0.xy)) + r0;
    r0 = SampleOffsetsWeights[6].z * tex2D(Source, (SampleOffsetsWeights[6].xy + texcoord0.xy)) + r0;
    r0 = SampleOffsetsWeights[7].z * tex2D(Source, (SampleOffsetsWeights[7].xy + texcoord0.xy)) + r0;
    r0 = SampleOffsetsWeights[8].z * tex2D(Source, (SampleOffsetsWeights[8].xy + texcoord0.xy)) + r0;
    r0 = SampleOffsetsWeights[9].z * tex2D(Source, (SampleOffsetsWeights[9].xy + texcoord0.xy)) + r0;
    r0 = SampleOffsetsWeights[10].z * tex2D(Source, (SampleOffsetsWeights[10].xy + texcoord0.xy)) + r0;
    r0 = SampleOffsetsWeights[11].z * tex2D(Source, (SampleOffsetsWeights[11].xy + texcoord0.xy)) + r0;
    oC0 = SampleOffsetsWeights[12].z * tex2D(Source, (SampleOffsetsWeights[12].xy + texcoord0.xy)) + r0;
    return oC0;
}
