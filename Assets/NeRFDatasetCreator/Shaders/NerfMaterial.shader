// The Built-in pipeline's material passes (issue 38), drawn by MaterialPassRenderer with CommandBuffer.DrawRenderer
// outside any camera, like NerfData.shader: no lighting, fog, post-processing or MSAA; a float target with no sRGB write.
// One material of this shader stands in for each Standard / Standard (Specular setup) source material, with the
// source's values copied into properties DECLARED EXACTLY AS Standard.shader declares them (same names, same [Gamma]
// attribute on _Metallic, Color type for the colours), so Unity applies the same colour-space conversions and the
// fragment sees the values the Standard shader sees. Sources (Unity built-in shaders as stored in
// TwoTailsGames/Unity-Built-in-Shaders 09db4ee): Standard.shader:7-32 (properties), StandardSpecular.shader:15-16,
// UnityStandardInput.cginc:72-78 TexCoords (every map uses uv0 through _MainTex_ST), :85-108 Albedo, :131-151
// SpecularGloss, :153-174 MetallicGloss, :193-200 Emission. Detail and parallax maps are not reproduced: such materials
// are reported unsupported (Core MaterialShaderSupport).
// Pass 0 = base colour, 1 = metallic, 2 = smoothness, 3 = specular colour, 4 = emission, 5 = coverage
// (R = supported, G = specular setup). Cull and alpha clip are the data passes' (_NerfCull, _NerfClip from Core's
// DataPassRules), so every pass covers what the mask covers.
Shader "Hidden/NerfDatasetCreator/Material"
{
    Properties
    {
        _NerfCull ("Cull", Float) = 2
        _NerfClip ("Alpha clip", Float) = 0
        _NerfCutoff ("Alpha cutoff", Float) = 0.5
        _NerfColorAlpha ("Colour alpha", Float) = 1
        _NerfAlphaTex ("Alpha texture", 2D) = "white" {}

        _Color ("Color", Color) = (1,1,1,1)
        _MainTex ("Albedo", 2D) = "white" {}
        _Glossiness ("Smoothness", Range(0.0, 1.0)) = 0.5
        _GlossMapScale ("Smoothness Scale", Range(0.0, 1.0)) = 1.0
        [Gamma] _Metallic ("Metallic", Range(0.0, 1.0)) = 0.0
        _MetallicGlossMap ("Metallic", 2D) = "white" {}
        _NerfSpecColor ("Specular (the source's _SpecColor)", Color) = (0.2, 0.2, 0.2, 1)
        _SpecGlossMap ("Specular", 2D) = "white" {}
        _EmissionColor ("Color", Color) = (0,0,0,1)
        _EmissionMap ("Emission", 2D) = "white" {}

        // The source's keywords as numbers (0/1), so one variant serves every material.
        _NerfMetallicMap ("_METALLICGLOSSMAP", Float) = 0
        _NerfSpecMap ("_SPECGLOSSMAP", Float) = 0
        _NerfSmoothnessFromAlbedo ("_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A", Float) = 0
        _NerfEmission ("_EMISSION", Float) = 0
        _NerfSpecularSetup ("Standard (Specular setup)", Float) = 0
        _NerfSupported ("Read exactly", Float) = 0
    }

    CGINCLUDE
    #include "UnityCG.cginc"

    sampler2D _NerfAlphaTex;
    float4 _NerfAlphaTex_ST;
    float _NerfClip, _NerfCutoff, _NerfColorAlpha;

    float4 _Color;
    sampler2D _MainTex;
    float4 _MainTex_ST;
    float _Glossiness, _GlossMapScale, _Metallic;
    sampler2D _MetallicGlossMap;
    float4 _NerfSpecColor;
    sampler2D _SpecGlossMap;
    float4 _EmissionColor;
    sampler2D _EmissionMap;
    float _NerfMetallicMap, _NerfSpecMap, _NerfSmoothnessFromAlbedo, _NerfEmission, _NerfSpecularSetup, _NerfSupported;

    struct appdata
    {
        float4 vertex : POSITION;
        float2 uv : TEXCOORD0;
    };

    struct v2f
    {
        float4 pos : SV_POSITION;
        float2 alphaUv : TEXCOORD0;
        float2 uv : TEXCOORD1;
    };

    v2f vert(appdata v)
    {
        v2f o;
        o.pos = UnityObjectToClipPos(v.vertex.xyz);
        o.alphaUv = TRANSFORM_TEX(v.uv, _NerfAlphaTex);
        o.uv = TRANSFORM_TEX(v.uv, _MainTex); // TexCoords(): texcoord.xy, used by every map below
        return o;
    }

    void ClipLikeTheSource(float2 uv)
    {
        float alpha = tex2D(_NerfAlphaTex, uv).a * _NerfColorAlpha;
        clip(_NerfClip > 0.5 ? alpha - _NerfCutoff : 1.0);
    }

    // Albedo(): _Color.rgb * tex2D(_MainTex, uv).rgb (no detail map).
    float3 BaseColour(float2 uv) { return _Color.rgb * tex2D(_MainTex, uv).rgb; }

    // MetallicGloss() (metallic setup) and SpecularGloss() (specular setup): .a = smoothness.
    float4 SpecularOrMetallicGloss(float2 uv)
    {
        float albedoAlpha = tex2D(_MainTex, uv).a;
        float4 g;
        if (_NerfSpecularSetup > 0.5)
        {
            if (_NerfSpecMap > 0.5)
            {
                g = tex2D(_SpecGlossMap, uv);
                if (_NerfSmoothnessFromAlbedo > 0.5) g.a = albedoAlpha;
                g.a *= _GlossMapScale;
            }
            else
            {
                g.rgb = _NerfSpecColor.rgb;
                g.a = _NerfSmoothnessFromAlbedo > 0.5 ? albedoAlpha * _GlossMapScale : _Glossiness;
            }
        }
        else
        {
            if (_NerfMetallicMap > 0.5)
            {
                float4 m = tex2D(_MetallicGlossMap, uv);
                g = float4(m.r, m.r, m.r, _NerfSmoothnessFromAlbedo > 0.5 ? albedoAlpha : m.a);
                g.a *= _GlossMapScale;
            }
            else
            {
                g = float4(_Metallic, _Metallic, _Metallic, _NerfSmoothnessFromAlbedo > 0.5 ? albedoAlpha * _GlossMapScale : _Glossiness);
            }
        }
        return g;
    }

    // Emission(): 0 without _EMISSION, else tex2D(_EmissionMap, uv).rgb * _EmissionColor.rgb.
    float3 EmissionColour(float2 uv) { return _NerfEmission > 0.5 ? tex2D(_EmissionMap, uv).rgb * _EmissionColor.rgb : float3(0, 0, 0); }
    ENDCG

    SubShader
    {
        Tags { "RenderType" = "Opaque" "Queue" = "Geometry" }

        Pass
        {
            Name "BaseColour"
            Cull [_NerfCull] ZWrite On ZTest LEqual Blend Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target { ClipLikeTheSource(i.alphaUv); return float4(BaseColour(i.uv), 1); }
            ENDCG
        }

        Pass
        {
            Name "Metallic"
            Cull [_NerfCull] ZWrite On ZTest LEqual Blend Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target
            {
                ClipLikeTheSource(i.alphaUv);
                float m = _NerfSpecularSetup > 0.5 ? 0 : SpecularOrMetallicGloss(i.uv).r;
                return float4(m, m, m, 1);
            }
            ENDCG
        }

        Pass
        {
            Name "Smoothness"
            Cull [_NerfCull] ZWrite On ZTest LEqual Blend Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target
            {
                ClipLikeTheSource(i.alphaUv);
                float s = SpecularOrMetallicGloss(i.uv).a;
                return float4(s, s, s, 1);
            }
            ENDCG
        }

        Pass
        {
            Name "Specular"
            Cull [_NerfCull] ZWrite On ZTest LEqual Blend Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target
            {
                ClipLikeTheSource(i.alphaUv);
                float3 s = _NerfSpecularSetup > 0.5 ? SpecularOrMetallicGloss(i.uv).rgb : float3(0, 0, 0);
                return float4(s, 1);
            }
            ENDCG
        }

        Pass
        {
            Name "Emission"
            Cull [_NerfCull] ZWrite On ZTest LEqual Blend Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target { ClipLikeTheSource(i.alphaUv); return float4(EmissionColour(i.uv), 1); }
            ENDCG
        }

        // Coverage: every drawn renderer writes (supported, specular setup), so an unsupported object in front hides a
        // supported one behind it, as in the colour image.
        Pass
        {
            Name "Coverage"
            Cull [_NerfCull] ZWrite On ZTest LEqual Blend Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 frag(v2f i) : SV_Target { ClipLikeTheSource(i.alphaUv); return float4(_NerfSupported, _NerfSpecularSetup, 0, 1); }
            ENDCG
        }
    }
    Fallback Off
}
