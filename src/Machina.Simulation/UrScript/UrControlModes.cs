namespace Machina.Simulation.UrScript;

/// <summary>
/// The control settings a program switches that the twin accepts without a physical model behind them: force mode, freedrive,
/// the gravity direction and the force/torque sensor. Kept so that a program and a test can see them.
/// </summary>
internal sealed class UrControlModes
{
    private readonly Lock _gate = new();
    private bool _forceMode;
    private bool _freedrive;
    private double[] _gravity = [0, 0, 9.82];
    private double[] _payloadCog = [0, 0, 0];

    /// <summary>Force mode is on (<c>force_mode</c> until <c>end_force_mode</c>).</summary>
    public bool ForceMode
    {
        get
        {
            lock (_gate)
            {
                return _forceMode;
            }
        }
        set
        {
            lock (_gate)
            {
                _forceMode = value;
            }
        }
    }

    /// <summary>Freedrive is on (<c>freedrive_mode</c> until <c>end_freedrive_mode</c>).</summary>
    public bool Freedrive
    {
        get
        {
            lock (_gate)
            {
                return _freedrive;
            }
        }
        set
        {
            lock (_gate)
            {
                _freedrive = value;
            }
        }
    }

    /// <summary>The gravity vector in the base frame, m/s² (<c>set_gravity</c>; default straight down, 9.82).</summary>
    public double[] Gravity
    {
        get
        {
            lock (_gate)
            {
                return [.. _gravity];
            }
        }
        set
        {
            lock (_gate)
            {
                _gravity = [.. value];
            }
        }
    }

    /// <summary>The payload's centre of gravity from the flange, m (<c>set_payload</c>, <c>set_target_payload</c>).</summary>
    public double[] PayloadCog
    {
        get
        {
            lock (_gate)
            {
                return [.. _payloadCog];
            }
        }
        set
        {
            lock (_gate)
            {
                _payloadCog = [.. value];
            }
        }
    }

    /// <summary>Back to the start (a new program): no force mode, no freedrive. Gravity is the controller's and stays.</summary>
    public void Reset()
    {
        lock (_gate)
        {
            _forceMode = false;
            _freedrive = false;
        }
    }
}
