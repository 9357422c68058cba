// ps_3_0 shader decompiled by ps30
float4 abcdefghijk : register(c20);
float4 arr[20] : register(c0);
float4 bb : register(c21); // the table's type: bool
int4 n : register(i0);

float4 main() : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0, r6 = 0, r7 = 0;
    r0 = 0.0;
    r1.x = 0.0;
    for (int n0 = 0; n0 < n.x; n0++) {
        r2 = r1.x + float4(-0.0, -1.0, -2.0, -3.0);
        r3 = r1.x + float4(-4.0, -5.0, -6.0, -7.0);
        r4 = r1.x + float4(-8.0, -9.0, -10.0, -11.0);
        r5 = r1.x + float4(-12.0, -13.0, -14.0, -15.0);
        r6 = r1.x + float4(-16.0, -17.0, -18.0, -19.0);
        r7 = -abs(r2.x) >= 0.0 ? arr[0] : 0.0;
        r7 = -abs(r2.z) >= 0.0 ? arr[2] : (-abs(r2.y) >= 0.0 ? arr[1] : r7);
        r2 = -abs(r2.w) >= 0.0 ? arr[3] : r7;
        r2 = -abs(r3.y) >= 0.0 ? arr[5] : (-abs(r3.x) >= 0.0 ? arr[4] : r2);
        r2 = -abs(r3.w) >= 0.0 ? arr[7] : (-abs(r3.z) >= 0.0 ? arr[6] : r2);
        r2 = -abs(r4.y) >= 0.0 ? arr[9] : (-abs(r4.x) >= 0.0 ? arr[8] : r2);
        r2 = -abs(r4.w) >= 0.0 ? arr[11] : (-abs(r4.z) >= 0.0 ? arr[10] : r2);
        r2 = -abs(r5.y) >= 0.0 ? arr[13] : (-abs(r5.x) >= 0.0 ? arr[12] : r2);
        r2 = -abs(r5.w) >= 0.0 ? arr[15] : (-abs(r5.z) >= 0.0 ? arr[14] : r2);
        r2 = -abs(r6.y) >= 0.0 ? arr[17] : (-abs(r6.x) >= 0.0 ? arr[16] : r2);
        r2 = -abs(r6.w) >= 0.0 ? arr[19] : (-abs(r6.z) >= 0.0 ? arr[18] : r2);
        r0 = r0 + r2;
        r1.x = r1.x + 1.0;
    }
    oC0 = -bb.x >= 0.0 ? r0 : (r0 + abcdefghijk);
    return oC0;
}
