#!/bin/bash
# session 2026-11-27: after the modelling choices, remake the 2000 and 4000 rpm shaft-centre points
# with the new stop rule, then check the rule at 4000 rpm by running that case on to 10.5 revolutions.
cd /work/main
while pgrep -f cfd_modelling_choices >/dev/null; do sleep 20; done
echo "== 2000 rpm $(date)"
D=results/cfd/oilbath_real/32208_2000rpm_shaft_center_tiny_g0.08
if [ ! -d $D ]; then mkdir -p results/cfd/oilbath_real && cp -a results/cfd/moving_mesh/frozen_2000rpm_tiny $D && rm -f $D/results.json; fi
.venv/bin/kegel cfd run --bearing 32208 --speed "2000 rpm" --oil-level shaft_center --mesh tiny --np 2 \
    --gap-ratio 0.08 --max-courant 10 --max-interface-courant 3 --max-wall-time "50 min" --output $D --quiet
echo "== 4000 rpm $(date)"
D4=results/cfd/oilbath_real/32208_4000rpm_shaft_center_tiny_g0.08
.venv/bin/kegel cfd run --bearing 32208 --speed "4000 rpm" --oil-level shaft_center --mesh tiny --np 2 \
    --gap-ratio 0.08 --max-courant 10 --max-interface-courant 3 --max-wall-time "50 min" --output $D4 --quiet
echo "== 4000 rpm run on $(date)"
W=results/cfd/stop_rule_real_4000
if [ ! -d $W/reference ]; then mkdir -p $W && cp -a $D4 $W/reference && rm -f $W/reference/results.json; fi
.venv/bin/python benchmarks/cfd_oil_bath_stop_rule.py --work $W --speed 4000 --end-time 0.376
echo "== done $(date)"
