using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What <see cref="DataPassRules"/> needs to know of a Unity material, read by the Editor layer: its shader's name,
    /// whether Shader Graph generated that shader, and the values of the properties and keywords listed in
    /// <see cref="DataPassRules"/> that the material has. A property the material lacks is simply absent.
    /// </summary>
    public sealed class MaterialSnapshot
    {
        public MaterialSnapshot(string shaderName, bool isShaderGraph = false)
        {
            ShaderName = shaderName ?? "";
            IsShaderGraph = isShaderGraph;
        }

        public string ShaderName { get; }

        /// <summary>True when the shader carries Shader Graph's <c>"ShaderGraphShader"="true"</c> SubShader tag.</summary>
        public bool IsShaderGraph { get; }

        /// <summary>Float (and Range) properties by name.</summary>
        public Dictionary<string, double> Floats { get; } = new Dictionary<string, double>(StringComparer.Ordinal);

        /// <summary>The alpha of colour properties by name.</summary>
        public Dictionary<string, double> ColorAlphas { get; } = new Dictionary<string, double>(StringComparer.Ordinal);

        /// <summary>Texture properties the shader declares (assigned or not: an empty slot samples the shader's default).</summary>
        public HashSet<string> Textures { get; } = new HashSet<string>(StringComparer.Ordinal);

        /// <summary>Enabled shader keywords.</summary>
        public HashSet<string> Keywords { get; } = new HashSet<string>(StringComparer.Ordinal);

        public MaterialSnapshot WithFloat(string name, double value)
        {
            Floats[name] = value;
            return this;
        }

        public MaterialSnapshot WithColorAlpha(string name, double alpha)
        {
            ColorAlphas[name] = alpha;
            return this;
        }

        public MaterialSnapshot WithTexture(string name)
        {
            Textures.Add(name);
            return this;
        }

        public MaterialSnapshot WithKeyword(string keyword)
        {
            Keywords.Add(keyword);
            return this;
        }
    }
}
