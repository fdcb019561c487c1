using System.Globalization;
using System.Text;

namespace Machina;

/// <summary>
/// Text of the KUKA link written into a span while it fits and every number takes the fixed-point writer, then into a builder
/// (the span's characters first): one writer for both, so the two give the same characters by construction. What the host
/// streams (a batch of one action) stays on the stack; a long message or a value of 10^9 or more goes on in the builder.
/// </summary>
internal ref struct KukaText
{
    private readonly Span<char> _span;
    private int _length;
    private StringBuilder? _builder;

    /// <summary>Text written into <paramref name="span"/> until it does not fit.</summary>
    public KukaText(Span<char> span)
    {
        _span = span;
    }

    /// <summary>Text appended to <paramref name="builder"/> from the start.</summary>
    public KukaText(StringBuilder builder)
    {
        _span = default;
        _builder = builder;
    }

    /// <summary>The builder the text went on in, or null while all of it is in the span.</summary>
    public readonly StringBuilder? Builder => _builder;

    /// <summary>The characters written into the span (all of the text while <see cref="Builder"/> is null).</summary>
    public readonly ReadOnlySpan<char> Written => _span[.._length];

    /// <summary>Appends <paramref name="text"/> as it is.</summary>
    public void Append(scoped ReadOnlySpan<char> text)
    {
        if (_builder is null && text.TryCopyTo(_span[_length..]))
        {
            _length += text.Length;
            return;
        }
        Spill().Append(text);
    }

    /// <summary>Appends a whole number (an id, an action code).</summary>
    public void Append(int value)
    {
        if (_builder is null && value.TryFormat(_span[_length..], out int written, default, CultureInfo.InvariantCulture))
        {
            _length += written;
            return;
        }
        Spill().Append(CultureInfo.InvariantCulture, $"{value}");
    }

    /// <summary>Appends a number with at most <paramref name="decimals"/> decimals, never in exponent form and never "-0" (<see cref="NumAppend.AppendFixed"/>).</summary>
    public void AppendFixed(double value, int decimals)
    {
        if (_builder is null && _span.Length - _length >= NumAppend.MaxChars)
        {
            int written = NumAppend.TryWriteScaled(_span[_length..], value, decimals);
            if (written >= 0)
            {
                _length += written;
                return;
            }
        }
        Spill().AppendFixed(value, decimals);
    }

    /// <summary>Appends <paramref name="text"/> escaped for an attribute value or element content (<see cref="KukaXml.Escape"/>).</summary>
    public void AppendEscaped(string text)
    {
        foreach (char c in text)
        {
            if (KukaXml.Escape(c, out char plain) is string entity)
            {
                Append(entity);
            }
            else if (_builder is null && _length < _span.Length)
            {
                _span[_length++] = plain;
            }
            else
            {
                Spill().Append(plain);
            }
        }
    }

    /// <summary>The builder from now on, holding what the span has so far.</summary>
    private StringBuilder Spill() => _builder ??= new StringBuilder(_length + 256).Append(_span[.._length]);
}
