# The four cameras of the football-field figures and the plan benchmark (sourced):
# name, eye x,y,z, target x,y,z. High overview, player height, an ant's eye, grazing.
football_cameras=(
  "high 47.5,60,-40 47.5,0,80"
  "player 47.5,1.7,6 47.5,0,60"
  "ant 47.3,0.05,6 47.3,0.04,20"
  "grazing 47.3,3,-2 47.3,2.9,400"
)
