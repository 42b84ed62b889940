exactccd check --stats data/sim/*.csv                      # the oracle: answers, FP/FN, stages
exactccd check --method naive data/sim/*vertex-face.csv    # the textbook cubic's mistakes
exactccd check --min-distance 1e-3 --toi --answers data/sim/sim-cloth-vertex-face.csv | grep '^1 ' | sed -n 1,3p
exactccd scene data/scenes/cloth/T0.obj data/scenes/cloth/T1.obj | sed -n 1,4p
