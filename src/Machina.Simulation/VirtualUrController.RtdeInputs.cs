using System.Buffers.Binary;
using System.Text;
using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;
using Packages = Machina.Simulation.VirtualUrRtdePackages;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>Which connection holds each input name: a UR gives an input to one client at a time (others get IN_USE).</summary>
    private readonly Dictionary<string, RtdeSubscriber> _inputOwners = new(StringComparer.Ordinal);

    /// <summary>The type a setup answers for an input another client holds.</summary>
    private const string InUse = "IN_USE";

    /// <summary>
    /// RTDE input setup: the recipe's types (NOT_FOUND for a name the guide does not have, IN_USE for one another client holds)
    /// with a new recipe id, or id 0 when any name failed (the recipe is not set up).
    /// </summary>
    private void SetupInputs(ReadOnlySpan<byte> payload, RtdeSubscriber subscriber, VirtualUrRtdeWriter reply)
    {
        string[] names = VirtualUrRtdeFields.Recipe(Encoding.ASCII.GetString(payload));
        string[] types;
        byte id = 0;
        lock (_rtdeGate)
        {
            types = [.. names.Select(n => VirtualUrRtdeFields.InputType(n) is var t && t != Packages.NotFound
                && _inputOwners.TryGetValue(n, out RtdeSubscriber? owner) && owner != subscriber ? InUse : t)];
            if (types.All(t => t is not (Packages.NotFound or InUse)))
            {
                id = subscriber.NextInputRecipe();
                subscriber.InputRecipes[id] = (names, types);
                foreach (string name in names)
                {
                    _inputOwners[name] = subscriber;
                }
            }
        }
        reply.Byte(id);
        reply.Ascii(string.Join(',', types));
    }

    /// <summary>Gives back the inputs a closed connection held.</summary>
    private void ReleaseInputs(RtdeSubscriber subscriber)
    {
        lock (_rtdeGate)
        {
            foreach (string name in _inputOwners.Where(p => p.Value == subscriber).Select(p => p.Key).ToArray())
            {
                _inputOwners.Remove(name);
            }
        }
    }

    /// <summary>
    /// An input data package (recipe id, then each value of the recipe): registers the program reads
    /// (<c>read_input_integer_register</c>…), outputs under their masks, the speed slider. A package of an unknown recipe or
    /// of the wrong length is refused (recorded), as a UR ignores it. Each name is an update for a watchdog on it (<c>rtde_set_watchdog</c>).
    /// </summary>
    private void ApplyInputs(ReadOnlySpan<byte> payload, RtdeSubscriber subscriber)
    {
        if (payload.Length == 0 || !subscriber.InputRecipes.TryGetValue(payload[0], out var recipe))
        {
            RecordError($"RTDE: input data for recipe {(payload.Length == 0 ? "(none)" : payload[0].ToString(Num.Inv))}, which was not set up.");
            return;
        }
        int expected = 1 + recipe.Types.Sum(Packages.SizeOf);
        if (payload.Length != expected)
        {
            RecordError($"RTDE: input data of {payload.Length} bytes for recipe {payload[0].ToString(Num.Inv)}, which takes {expected}.");
            return;
        }
        int at = 1;
        Dictionary<string, double> values = subscriber.InputValues;
        for (int i = 0; i < recipe.Names.Length; i++)
        {
            string name = recipe.Names[i], type = recipe.Types[i];
            ReadOnlySpan<byte> value = payload.Slice(at, Packages.SizeOf(type));
            at += value.Length;
            values[name] = type switch
            {
                "BOOL" or "UINT8" => value[0],
                "UINT32" => BinaryPrimitives.ReadUInt32BigEndian(value),
                "INT32" => BinaryPrimitives.ReadInt32BigEndian(value),
                "DOUBLE" => BinaryPrimitives.ReadDoubleBigEndian(value),
                _ => 0, // external_force_torque: the twin has no force sensing
            };
            ApplyRegister(name, values[name]);
            Twin.Watchdog.Updated(name);
        }
        ApplyMasked(recipe.Names, values);
    }

    /// <summary>An input register the running program reads.</summary>
    private void ApplyRegister(string name, double value)
    {
        TwinIo io = Twin.Io;
        if (VirtualUrRtdeFields.RegisterNumber(name, "input_bit_register_") is int bit and >= 0)
        {
            io.SetBit(UrIoBanks.InputBoolRegisters, bit, value != 0);
        }
        else if (VirtualUrRtdeFields.RegisterNumber(name, "input_int_register_") is int integer and >= 0)
        {
            io.SetNumber(UrIoBanks.InputIntRegisters, integer, value);
        }
        else if (VirtualUrRtdeFields.RegisterNumber(name, "input_double_register_") is int number and >= 0)
        {
            io.SetNumber(UrIoBanks.InputFloatRegisters, number, value);
        }
        else if (name is "input_bit_registers0_to_31" or "input_bit_registers32_to_63")
        {
            int first = name.Contains("32_to", StringComparison.Ordinal) ? 32 : 0;
            uint word = (uint)value;
            for (int i = 0; i < 32; i++)
            {
                io.SetBit(UrIoBanks.InputBoolRegisters, first + i, (word >> i & 1) != 0);
            }
        }
    }

    /// <summary>The inputs that act under a mask (outputs, speed slider), each with the last mask and value this client sent.</summary>
    private void ApplyMasked(string[] names, Dictionary<string, double> values)
    {
        TwinIo io = Twin.Io;
        double Last(string name) => values.TryGetValue(name, out double v) ? v : 0;
        bool Sent(string group) => names.Any(n => n.StartsWith(group, StringComparison.Ordinal));
        foreach ((string group, string bank, int count) in (ReadOnlySpan<(string, string, int)>)[
            ("standard_digital_output", UrIoBanks.StandardOut, 8), ("configurable_digital_output", UrIoBanks.ConfigurableOut, 8), ("tool_digital_output", UrIoBanks.ToolOut, 2)])
        {
            if (Sent(group))
            {
                int mask = (int)Last(group + "_mask"), bits = (int)Last(group);
                for (int i = 0; i < count; i++)
                {
                    if ((mask >> i & 1) != 0)
                    {
                        io.SetBit(bank, i, (bits >> i & 1) != 0);
                    }
                }
            }
        }
        if (Sent("standard_analog_output"))
        {
            int mask = (int)Last("standard_analog_output_mask");
            for (int i = 0; i < 2; i++)
            {
                if ((mask >> i & 1) != 0)
                {
                    io.SetNumber(UrIoBanks.AnalogOut, i, Last("standard_analog_output_" + i.ToString(Num.Inv)));
                }
            }
        }
        if (Sent("speed_slider") && ((int)Last("speed_slider_mask") & 1) != 0)
        {
            lock (Gate)
            {
                _speedSlider = Math.Clamp(Last("speed_slider_fraction"), 0, 1);
            }
        }
    }
}
