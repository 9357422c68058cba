// oracle: target=ps_2_a
// ps_2_x shader decompiled by ps30 (HLSL for ps_2_a)

float4 main(float4 texcoord0 : TEXCOORD0) : COLOR
{
    precise float4 oC0 = 0;
    precise float4 r0 = 0, r1 = 0, r2 = 0;
    r0 = float4(1.0, 0.5, 0.25, 2.0);
    r1 = float4(1.0, 0.5, 0.25, 2.0);
    r2 = float4(1.0, 0.5, 0.25, 2.0);
    for (int n0 = 0; n0 < int4(2, 0, 0, 0).x; n0++) {
        if (r1.x > r2.x) {
            if (r1.x > r2.x) {
                if (r1.x > r2.x) {
                    if (r1.x > r2.x) {
                        if (r1.x > r2.x) {
                            if (r1.x > r2.x) {
                                if (r1.x > r2.x) {
                                    if (r1.x > r2.x) {
                                        if (r1.x > r2.x) {
                                            if (r1.x > r2.x) {
                                                if (r1.x > r2.x) {
                                                    if (r1.x > r2.x) {
                                                        if (r1.x > r2.x) {
                                                            if (r1.x > r2.x) {
                                                                if (r1.x > r2.x) {
                                                                    if (r1.x > r2.x) {
                                                                        if (r1.x > r2.x) {
                                                                            if (r1.x > r2.x) {
                                                                                if (r1.x > r2.x) {
                                                                                    if (r1.x > r2.x) {
                                                                                        if (r1.x > r2.x) {
                                                                                            if (r1.x > r2.x) {
                                                                                                if (r1.x > r2.x) {
                                                                                                    if (r1.x > r2.x) break;
                                                                                                }
                                                                                            }
                                                                                        }
                                                                                    }
                                                                                }
                                                                            }
                                                                        }
                                                                    }
                                                                }
                                                            }
                                                        }
                                                    }
                                                }
                                            }
                                        }
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    oC0 = r0;
    return oC0;
}
